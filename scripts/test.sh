#!/usr/bin/env bash
# Installs the dependencies, builds JTracer and runs the whole test suite:
# the release build first (and what it installs and packages: install-test.sh),
# then the fuzz targets (built with clang, each run for JT_FUZZ_SECONDS,
# default 30), then everything again under ASan + UBSan, whose jtracer-cli,
# built at another optimisation level, must render the release build's bytes
# (cli_isa_identity).
# Set JT_SKIP_FUZZ=1 or JT_SKIP_ASAN=1 to leave those steps out.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh

jobs=$(nproc)
# Each stage's header says how long the run has taken so far.
stage() {
    printf '== [%d:%02d] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$*"
}
run_preset() {
    local preset=$1
    shift
    stage "$preset: configure and build"
    cmake --preset "$preset" >/dev/null
    cmake --build --preset "$preset" -j "$jobs"
    stage "$preset: tests"
    # One test more than the cores: several tests spend most of their time
    # waiting (the MPI network test on its timeouts, the viewer's on frames).
    ctest --preset "$preset" -j "$((jobs + 1))" "$@"
    # pytest's own summary of the Python module's tests: ctest keeps the output
    # of a test that passed only in its log.
    sed -n 's/^\(=\+ .* in [0-9.]\+s.* =\+\)$/python_module: \1/p' \
        "build/$preset/Testing/Temporary/LastTest.log"
}

run_preset release
stage "release: install, package, uninstall"
./scripts/install-test.sh build/release
if [ "${JT_SKIP_FUZZ:-0}" != 1 ]; then
    stage "fuzz"
    # A fixed seed: the suite checks that the fuzzers find nothing new along a
    # known path; looking for new findings is the long runs' job (docs/hardening.md).
    JT_FUZZ_SEED=${JT_FUZZ_SEED:-1} ./scripts/fuzz.sh "${JT_FUZZ_SECONDS:-30}"
fi
if [ "${JT_SKIP_ASAN:-0}" != 1 ]; then
    # The install tests check files and scripts the release stage installed
    # already; under the sanitizers they would run no code of ours.
    run_preset asan -E '^install_'
fi
stage "done"

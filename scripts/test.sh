#!/usr/bin/env bash
# Installs the dependencies, builds JTracer and runs the whole test suite:
# the release build first (and what it installs and packages: install-test.sh),
# then everything again under ASan + UBSan, whose jtracer-cli, built at another
# optimisation level, must render the release build's bytes (cli_isa_identity),
# then the fuzz targets (built with clang, each run for JT_FUZZ_SECONDS,
# default 30).
# Set JT_SKIP_FUZZ=1 or JT_SKIP_ASAN=1 to leave those steps out.
#
# The machine's cores are the limit, and the test stages leave them idle a
# good part of the time (tests waiting on timeouts, frames, other processes):
# the next stage's build runs beside them, at a lower priority so that the
# tests run as they would alone (CONTRIBUTING.md gives each stage's time).
# When ccache is installed the builds go through it (JT_CCACHE=0: not).
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh

jobs=$(nproc)
clock_ticks=$(getconf CLK_TCK)
# CPU seconds (user + system) of the processes this shell has waited for,
# read from /proc without starting one.
cpu_seconds() {
    local line fields
    read -r line </proc/$$/stat
    # After the command name (in parentheses) come fields 3 on; 16 and 17
    # are cutime and cstime.
    read -r -a fields <<<"${line##*) }"
    echo $(((fields[13] + fields[14]) / clock_ticks))
}
# Each stage's header says how long the run has taken so far, in wall time and
# in CPU time of the stages finished.
stage() {
    printf '== [%d:%02d, %d CPU s] %s\n' $((SECONDS / 60)) $((SECONDS % 60)) "$(cpu_seconds)" "$*"
}

# An empty launcher undoes one a build folder was configured with before.
launcher=(-DCMAKE_C_COMPILER_LAUNCHER= -DCMAKE_CXX_COMPILER_LAUNCHER=)
if [ "${JT_CCACHE:-1}" != 0 ] && command -v ccache >/dev/null; then
    launcher=(-DCMAKE_C_COMPILER_LAUNCHER=ccache -DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
    # Paths below the checkout are hashed relative to it, so that clones in
    # other folders share the cache; the tests' precompiled header needs the
    # two pch sloppinesses (ccache's manual, "Precompiled headers").
    export CCACHE_BASEDIR=$PWD
    export CCACHE_SLOPPINESS=pch_defines,time_macros
fi

build() { # PRESET: configure and build in the foreground
    cmake --preset "$1" "${launcher[@]}" >/dev/null
    cmake --build --preset "$1" -j "$jobs"
}

# A build in the background, niced (10: about a tenth of a core against a
# test at the normal priority), its output kept in build/PRESET-build.log.
# Its own process group, so that finish_build can raise its priority back
# once nothing else of the run needs the cores.
declare -A background_pid
start_build() { # PRESET
    mkdir -p build
    stage "$1: configure and build (in the background, build/$1-build.log)"
    # shellcheck disable=SC2016 # the inner shell expands its own arguments
    setsid nice -n 10 bash -c 'set -e
        cmake --preset "$1" "${@:3}" >/dev/null
        cmake --build --preset "$1" -j "$2"
        echo "CPU time (user, system) of the shell, then of the build:"
        times' _ "$1" "$jobs" "${launcher[@]}" >"build/$1-build.log" 2>&1 &
    background_pid[$1]=$!
}
finish_build() { # PRESET: waits for start_build's build, then shows its output
    local preset=$1 pid=${background_pid[$1]}
    stage "$preset: waiting for the build"
    # Lowering a niceness needs root; a user's build just stays niced.
    renice -n 0 -g "$pid" >/dev/null 2>&1 || true
    local status=0
    wait "$pid" || status=$?
    unset "background_pid[$preset]"
    # ninja's progress lines, one per object, say little once the build is done.
    grep -v '^\[[0-9]*/[0-9]*\] ' "build/$preset-build.log" | sed "s/^/$preset build: /" || true
    if [ "$status" != 0 ]; then
        echo "$preset build FAILED (exit $status): the end of build/$preset-build.log:"
        tail -n 60 "build/$preset-build.log"
        exit "$status"
    fi
}
stop_builds() {
    local pid
    for pid in "${background_pid[@]}"; do
        kill -- -"$pid" 2>/dev/null || true
    done
}
trap stop_builds EXIT

run_tests() { # PRESET [CTEST ARGS...]
    local preset=$1
    shift
    stage "$preset: tests"
    # One test more than the cores: several tests spend most of their time
    # waiting (the MPI network test on its timeouts, the viewer's on frames).
    ctest --preset "$preset" -j "$((jobs + 1))" "$@"
    # pytest's own summary of the Python module's tests: ctest keeps the output
    # of a test that passed only in its log.
    sed -n 's/^\(=\+ .* in [0-9.]\+s.* =\+\)$/python_module: \1/p' \
        "build/$preset/Testing/Temporary/LastTest.log"
}

asan=0
[ "${JT_SKIP_ASAN:-0}" = 1 ] || asan=1
fuzz=0
[ "${JT_SKIP_FUZZ:-0}" = 1 ] || fuzz=1

stage "release: configure and build"
build release
[ "$asan" = 0 ] || start_build asan
run_tests release
stage "release: install, package, uninstall"
./scripts/install-test.sh build/release
if [ "$asan" = 1 ]; then
    finish_build asan
    [ "$fuzz" = 0 ] || start_build fuzz
    # The install tests check files and scripts the release stage installed
    # already; under the sanitizers they would run no code of ours.
    run_tests asan -E '^install_'
fi
if [ "$fuzz" = 1 ]; then
    [ "$asan" = 0 ] || finish_build fuzz
    stage "fuzz"
    # A fixed seed: the suite checks that the fuzzers find nothing new along a
    # known path; looking for new findings is the long runs' job (docs/hardening.md).
    JT_FUZZ_SEED=${JT_FUZZ_SEED:-1} ./scripts/fuzz.sh "${JT_FUZZ_SECONDS:-30}"
fi
stage "done"

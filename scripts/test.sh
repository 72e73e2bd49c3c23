#!/usr/bin/env bash
# Installs the dependencies, builds JTracer and runs the whole test suite:
# the release build first (and what it installs and packages: install-test.sh),
# then everything again under ASan + UBSan.
# Set JT_SKIP_ASAN=1 to run the release build only.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh

jobs=$(nproc)
run_preset() {
    local preset=$1
    echo "== $preset: configure and build"
    cmake --preset "$preset" >/dev/null
    cmake --build --preset "$preset" -j "$jobs"
    echo "== $preset: tests"
    ctest --preset "$preset" -j "$jobs"
}

run_preset release
echo "== release: install, package, uninstall"
./scripts/install-test.sh build/release
if [ "${JT_SKIP_ASAN:-0}" != 1 ]; then
    run_preset asan
fi

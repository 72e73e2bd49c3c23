#!/usr/bin/env bash
# Installs the dependencies, builds JTracer (release) and renders the bundled showcase scene.
set -euo pipefail
cd "$(dirname "$0")/.."
./scripts/install-deps.sh
cmake --preset release >/dev/null
cmake --build --preset release
scene=${1:-scenes/showcase.jts}
./build/release/cli/jtracer-cli "$scene"

#!/usr/bin/env bash
# One command from a fresh clone: installs POV-Ray when missing, builds the
# release CLI and the converter, generates the benchmark scenes, then races
# jtracer-cli against POV-Ray 3.7 and prints the table (bench/race.py).
#
#   bench/run.sh                    every scene, 5 runs each
#   bench/run.sh --quick            3 runs each, without the 1M-sphere scene
#   bench/run.sh --only showcase spheres_1m     some scenes only
#   bench/run.sh --runs 9 --threads 2
#
# Environment: JT_BENCH_BUILD (build dir, default build/bench), JT_BENCH_WORK
# (scenes, .pov files and images, default build/bench-work).
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${JT_BENCH_BUILD:-$repo/build/bench}"
work="${JT_BENCH_WORK:-$repo/build/bench-work}"
runs=5
threads=2
quick=0
only=()
while [[ $# -gt 0 ]]; do
    case "$1" in
        --quick) quick=1; runs=3; shift ;;
        --runs) runs="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --only) shift; while [[ $# -gt 0 && "$1" != --* ]]; do only+=("$1"); shift; done ;;
        -h|--help) sed -n '2,13p' "$0"; exit 0 ;;
        *) echo "run.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
done

as_root() {
    if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi
}

if ! command -v povray >/dev/null; then
    echo "== installing POV-Ray 3.7 (Debian package povray)"
    as_root apt-get update -q
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q povray
fi

echo "== building the release CLI and the converter in $build"
cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DJT_BUILD_TESTS=OFF -DJT_BUILD_VIEWER=OFF -DJT_BUILD_MPI=OFF -DJT_BUILD_BENCH=ON >/dev/null
cmake --build "$build" --target jtracer-cli jts-to-pov -- -j"$(nproc)"

echo "== generating scenes in $work/scenes"
generate=(python3 "$repo/bench/generate_scenes.py" "$work/scenes" --showcase "$repo/scenes/showcase.jts")
[[ $quick -eq 1 ]] && generate+=(--skip-million)
[[ ${#only[@]} -gt 0 ]] && generate+=(--only "${only[@]}")
"${generate[@]}" >/dev/null

race=(python3 "$repo/bench/race.py" --cli "$build/cli/jtracer-cli" --converter "$build/bench/jts-to-pov"
      --scenes "$work/scenes" --out "$work/images" --runs "$runs" --threads "$threads")
if [[ ${#only[@]} -gt 0 ]]; then
    race+=(--only "${only[@]}")
elif [[ $quick -eq 1 ]]; then
    race+=(--only showcase hall_of_mirrors forest lights16 spheres_1k spheres_10k spheres_100k)
fi
echo "== racing ($runs runs each, $threads threads); images in $work/images"
"${race[@]}"
echo "machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"

#!/usr/bin/env bash
# One command from a fresh clone: installs POV-Ray and Tachyon when missing,
# builds the release CLI and the converters, generates the benchmark scenes,
# then races jtracer-cli against Tachyon and POV-Ray 3.7 and prints the table
# (bench/race.py).
#
#   bench/run.sh                    every scene, 5 runs each
#   bench/run.sh --quick            3 runs each, 1920x1080 scenes of the Tachyon race and a few others
#   bench/run.sh --only showcase spheres_1m     some scenes only
#   bench/run.sh --runs 9 --threads 2 --no-povray
#   bench/run.sh --kernel-limit     instead of the race, JTracer's rays/s as a share of
#                                   Embree's native kernel (bench/kernel_limit.py) on the
#                                   1920x1080 scenes of the Tachyon race (or --only ...)
#   bench/run.sh --targets          every target of the race with PASS or MISS and by how
#                                   much (bench/targets.py): the race scenes at 1920x1080 and
#                                   1024x1024 and a million spheres at 320x240 and 1920x1080
#                                   against Tachyon and POV-Ray, each one's share of Embree's
#                                   kernel, mesh_1m under 3 s, a 1x1 render under 20 ms
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
race_options=()
kernel_limit=0
targets=0
while [[ $# -gt 0 ]]; do
    case "$1" in
        --quick) quick=1; runs=3; shift ;;
        --runs) runs="$2"; shift 2 ;;
        --threads) threads="$2"; shift 2 ;;
        --no-povray|--no-tachyon) race_options+=("$1"); shift ;;
        --kernel-limit) kernel_limit=1; shift ;;
        --targets) targets=1; shift ;;
        --only) shift; while [[ $# -gt 0 && "$1" != --* ]]; do only+=("$1"); shift; done ;;
        -h|--help) sed -n '2,22p' "$0"; exit 0 ;;
        *) echo "run.sh: unknown option '$1' (see --help)" >&2; exit 2 ;;
    esac
done

as_root() {
    if [[ $(id -u) -eq 0 ]]; then "$@"; else sudo "$@"; fi
}

missing=()
command -v povray >/dev/null || missing+=(povray)
command -v tachyon-nox >/dev/null || missing+=(tachyon-bin-nox)
if [[ ${#missing[@]} -gt 0 ]]; then
    echo "== installing ${missing[*]} (Debian packages)"
    as_root apt-get update -q
    as_root env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "${missing[@]}"
fi

echo "== building the release CLI and the converters in $build"
cmake -S "$repo" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release \
    -DJT_BUILD_TESTS=OFF -DJT_BUILD_VIEWER=OFF -DJT_BUILD_MPI=OFF -DJT_BUILD_BENCH=ON >/dev/null
cmake --build "$build" --target jtracer-cli jts-to-pov jts-to-tachyon kernel-limit -- -j"$(nproc)"

# The race against Tachyon's scenes at 1920x1080, and the scenes of the targets:
# generate_scenes.py and targets.py hold the lists.
mapfile -t race_scenes < <(python3 "$repo/bench/generate_scenes.py" --list-race)
mapfile -t target_scenes < <(python3 "$repo/bench/targets.py" --list-scenes)
[[ ${#race_scenes[@]} -gt 0 && ${#target_scenes[@]} -gt 0 ]] || {
    echo "run.sh: cannot list the scenes" >&2; exit 1; }
if [[ $targets -eq 1 && ${#only[@]} -eq 0 ]]; then
    only=("${target_scenes[@]}" mesh_1m)
fi

echo "== generating scenes in $work/scenes"
generate=(python3 "$repo/bench/generate_scenes.py" "$work/scenes" --showcase "$repo/scenes/showcase.jts")
[[ $quick -eq 1 ]] && generate+=(--skip-million)
[[ ${#only[@]} -gt 0 ]] && generate+=(--only "${only[@]}")
"${generate[@]}" >/dev/null

machine="machine: $(nproc) cores, $(lscpu | sed -n 's/^Model name: *//p')"
if [[ $kernel_limit -eq 1 ]]; then
    limit=(python3 "$repo/bench/kernel_limit.py" --cli "$build/cli/jtracer-cli"
           --kernel-limit "$build/bench/kernel-limit" --scenes "$work/scenes" --runs "$runs"
           --threads "$threads")
    if [[ ${#only[@]} -gt 0 ]]; then
        limit+=(--only "${only[@]}")
    else
        limit+=(--only "${race_scenes[@]}")
    fi
    echo "== JTracer against the kernel limit ($runs runs each, $threads threads)"
    "${limit[@]}"
    echo "$machine; Embree $(dpkg-query -W -f='${Version}' libembree3-3 2>/dev/null)"
    exit 0
fi

if [[ $targets -eq 1 ]]; then
    results="$work/targets"
    mkdir -p "$results"
    echo "== racing ($runs runs each, $threads threads); images in $work/images"
    python3 "$repo/bench/race.py" --cli "$build/cli/jtracer-cli" --converter "$build/bench/jts-to-pov" \
        --tachyon-converter "$build/bench/jts-to-tachyon" --scenes "$work/scenes" --out "$work/images" \
        --runs "$runs" --threads "$threads" "${race_options[@]}" --only "${only[@]}" \
        --json "$results/race.json"
    echo "== JTracer against the kernel limit ($runs runs each, $threads threads)"
    kernel_scenes=()
    for name in "${only[@]}"; do [[ $name == mesh_* ]] || kernel_scenes+=("$name"); done
    python3 "$repo/bench/kernel_limit.py" --cli "$build/cli/jtracer-cli" \
        --kernel-limit "$build/bench/kernel-limit" --scenes "$work/scenes" --runs "$runs" \
        --threads "$threads" --only "${kernel_scenes[@]}" --json "$results/kernel.json"
    echo "== start-up: a 1x1 render of few_1024, safe write included"
    python3 "$repo/bench/generate_scenes.py" "$work/scenes" --only few_1024 >/dev/null
    python3 "$repo/bench/startup_cost.py" --cli "$build/cli/jtracer-cli" --runs 21 \
        --threads "$threads" "$work/scenes/few_1024.jts" --json "$results/startup.json"
    echo "== the targets"
    python3 "$repo/bench/targets.py" --race "$results/race.json" --kernel "$results/kernel.json" \
        --startup "$results/startup.json"
    echo "$machine; povray $(dpkg-query -W -f='${Version}' povray 2>/dev/null);" \
        "tachyon-bin-nox $(dpkg-query -W -f='${Version}' tachyon-bin-nox 2>/dev/null);" \
        "Embree $(dpkg-query -W -f='${Version}' libembree3-3 2>/dev/null)"
    exit 0
fi

race=(python3 "$repo/bench/race.py" --cli "$build/cli/jtracer-cli" --converter "$build/bench/jts-to-pov"
      --tachyon-converter "$build/bench/jts-to-tachyon" --scenes "$work/scenes" --out "$work/images"
      --runs "$runs" --threads "$threads" "${race_options[@]}")
if [[ ${#only[@]} -gt 0 ]]; then
    race+=(--only "${only[@]}")
elif [[ $quick -eq 1 ]]; then
    race+=(--only showcase lights16 spheres_10k "${race_scenes[@]}")
fi
echo "== racing ($runs runs each, $threads threads); images in $work/images"
"${race[@]}"
echo "$machine; povray $(dpkg-query -W -f='${Version}' povray 2>/dev/null);" \
    "tachyon-bin-nox $(dpkg-query -W -f='${Version}' tachyon-bin-nox 2>/dev/null)"

#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang-14) and runs each for a bounded
# time: scripts/fuzz.sh [SECONDS_EACH] [TARGET...]   (default 60 s, both targets)
#
# Corpora, crash artifacts and logs (one per run, timestamped) go to
# build/fuzz/, never into the repo.
# A crashing input is saved as build/fuzz/artifacts/TARGET/crash-*; once fixed,
# copy it to tests/hardening/regressions/{parser,bmp}/ so that the test suite
# replays it. Exits non-zero when a target found a crash.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(parse_scene_fuzzer bmp_fuzzer)

out=build/fuzz
cmake -S fuzz -B "$out/build" -G Ninja -DCMAKE_CXX_COMPILER=clang++-14 \
    -DCMAKE_BUILD_TYPE=RelWithDebInfo >/dev/null
cmake --build "$out/build" -j 2 >/dev/null

# Seeds: the scenes and the regression inputs for the parser; BMPs written by
# the core's encoder and the regression inputs for the BMP reader.
seed_parser=$out/seeds/parse_scene_fuzzer
seed_bmp=$out/seeds/bmp_fuzzer
mkdir -p "$seed_parser" "$seed_bmp"
find scenes tests/hardening/regressions/parser -type f -exec cp {} "$seed_parser/" \; 2>/dev/null || true
"$out/build/make_bmp_seeds" "$seed_bmp"
find tests/hardening/regressions/bmp -type f -exec cp {} "$seed_bmp/" \; 2>/dev/null || true

status=0
stamp=$(date +%Y%m%d-%H%M%S)
for target in "${targets[@]}"; do
    corpus=$out/corpus/$target
    artifacts=$out/artifacts/$target
    mkdir -p "$corpus" "$artifacts"
    dict=()
    [ "$target" = parse_scene_fuzzer ] && dict=(-dict=fuzz/jts.dict)
    log=$out/$target-$stamp.log
    echo "== $target: $seconds s (log: $log)"
    if ! "$out/build/$target" "${dict[@]}" -max_total_time="$seconds" -timeout=60 \
        -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$artifacts/" "$corpus" "$out/seeds/$target" \
        >"$log" 2>&1; then
        status=1
        echo "   FOUND A CRASH: see $log and $artifacts/"
    fi
    grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' \
        "$log" | sed 's/^/   /' || true
    echo "   corpus: $(find "$corpus" -type f | wc -l) files"
done
exit $status

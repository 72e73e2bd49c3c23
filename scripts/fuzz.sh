#!/usr/bin/env bash
# Builds the libFuzzer targets (preset fuzz: clang 14, ASan + UBSan, over
# jtracer_scene) and runs each for a bounded time:
#   scripts/fuzz.sh [SECONDS_EACH] [TARGET...]   (default 60 s, every target)
#   JT_FUZZ_SEED=N scripts/fuzz.sh ...            (the same mutations every run)
#
# The build, corpora, crash artifacts and logs (one per run, timestamped) go to
# build/fuzz/, never into the repo.
# A crashing input is saved as build/fuzz/artifacts/TARGET/crash-*; once fixed,
# copy it to tests/hardening/regressions/{parser,bmp,image_map,model}/ so that the test suite
# replays it. Exits non-zero when the build fails or a target found a crash.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(parse_scene_fuzzer bmp_fuzzer image_map_fuzzer model_fuzzer)

out=build/fuzz
echo "== fuzz: configure and build"
cmake --preset fuzz >/dev/null
cmake --build --preset fuzz -j "$(nproc)"
bin=$out/fuzz

# Seeds: the scenes and the regression inputs for the parser; BMPs written by
# the core's encoder and the regression inputs for the BMP reader; pictures of
# every kind stb_image reads, the scenes' image maps and the regression inputs
# for the image-map loader; Assimp's test models (OBJ, PLY, STL, glTF of at
# most 300 KB) and the scenes' models for the model loader.
seed_parser=$out/seeds/parse_scene_fuzzer
seed_bmp=$out/seeds/bmp_fuzzer
seed_image=$out/seeds/image_map_fuzzer
seed_model=$out/seeds/model_fuzzer
mkdir -p "$seed_parser" "$seed_bmp" "$seed_image" "$seed_model"
find scenes tests/hardening/regressions/parser -type f -exec cp {} "$seed_parser/" \; 2>/dev/null || true
"$bin/make_bmp_seeds" "$seed_bmp"
find tests/hardening/regressions/bmp -type f -exec cp {} "$seed_bmp/" \; 2>/dev/null || true
"$bin/make_image_seeds" "$seed_image"
find scenes -name '*.png' -o -name '*.jpg' -o -name '*.bmp' | xargs -r cp -t "$seed_image/"
find tests/hardening/regressions/image_map -type f -exec cp {} "$seed_image/" \; 2>/dev/null || true
{ dpkg -L assimp-testmodels 2>/dev/null | grep -iE '\.(obj|ply|stl|gltf|glb)$' |
    xargs -r -d '\n' sh -c 'find "$@" -size -300k' sh; find scenes -type f; } |
    xargs -r -d '\n' "$bin/make_model_seeds" "$seed_model"
find tests/hardening/regressions/model -type f -exec cp {} "$seed_model/" \; 2>/dev/null || true

# Leaks inside Debian's Assimp are its own (fuzz/lsan-assimp.supp); ours still count.
export LSAN_OPTIONS=suppressions=$PWD/fuzz/lsan-assimp.supp:print_suppressions=0

# The targets run side by side (one core each), so the whole run takes about
# SECONDS_EACH; the summaries follow in order.
stamp=$(date +%Y%m%d-%H%M%S)
# JT_FUZZ_SEED fixes libFuzzer's random seed, so that a run from the same
# corpus mutates the same way every time (CI's run, scripts/test.sh, is then
# the same on every machine of the same speed); unset, each run differs.
seed=()
[ -n "${JT_FUZZ_SEED:-}" ] && seed=(-seed="$JT_FUZZ_SEED")
pids=()
for target in "${targets[@]}"; do
    corpus=$out/corpus/$target
    artifacts=$out/artifacts/$target
    mkdir -p "$corpus" "$artifacts"
    dict=()
    [ "$target" = parse_scene_fuzzer ] && dict=(-dict=fuzz/jts.dict)
    # Inputs up to 128 KiB: most test models are smaller, and larger ones slow
    # every execution down (a longer seed is cut to this length).
    [ "$target" = model_fuzzer ] && dict=(-max_len=131072)
    echo "== $target: $seconds s (log: $out/$target-$stamp.log)"
    "$bin/$target" "${dict[@]}" "${seed[@]}" -max_total_time="$seconds" -timeout=60 \
        -rss_limit_mb=2048 -print_final_stats=1 \
        -artifact_prefix="$artifacts/" "$corpus" "$out/seeds/$target" \
        >"$out/$target-$stamp.log" 2>&1 &
    pids+=($!)
done

status=0
for i in "${!targets[@]}"; do
    target=${targets[$i]}
    log=$out/$target-$stamp.log
    echo "== $target"
    if ! wait "${pids[$i]}"; then
        status=1
        echo "   FOUND A CRASH: see $log and $out/artifacts/$target/"
        tail -n 40 "$log" | sed 's/^/   | /'
    fi
    grep -E '^stat::(number_of_executed_units|average_exec_per_sec|peak_rss_mb)' \
        "$log" | sed 's/^/   /' || true
    echo "   corpus: $(find "$out/corpus/$target" -type f | wc -l) files"
done
exit $status

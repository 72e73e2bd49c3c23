#!/usr/bin/env bash
# The image must not depend on which vector unit Embree picks, nor on how
# JTracer was built. Renders every scene in scenes/ and BVH-sized scenes from
# the bench generator (thousands of overlapping spheres and cylinders) with
# Embree's default choice and forced to each ISA this CPU runs
# (JTRACER_EMBREE_CONFIG=isa=...), and with libjpeg-turbo's SIMD code off
# (JSIMD_FORCENONE=1), and requires identical bytes. The sums are
# kept in SUMS_DIR/BUILD.sums and compared with those of the other builds of
# the same revision (release, debug, sanitizers) found there.
# Usage: isa_identity_test.sh CLI SOURCE_DIR SUMS_DIR BUILD
set -euo pipefail
cli=$1 source_dir=$2 sums_dir=$3 build=$4
fail() {
    echo "FAIL: $*" >&2
    exit 1
}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

python3 "$source_dir/bench/generate_scenes.py" "$work/generated" \
    --only lattice_1024 nested_shells_1024 sphereflake_1024 tree_1024 >/dev/null
scenes=()
while IFS= read -r scene; do scenes+=("$scene"); done < <(
    find "$source_dir/scenes" "$work/generated" -name '*.jts' | sort)
[ ${#scenes[@]} -ge 10 ] || fail "only ${#scenes[@]} scenes found"

# An ISA is tried only when Embree runs it here; the config must take effect.
levels=(sse2 sse4.2 avx avx2 avx512)
isas=()
for i in "${!levels[@]}"; do
    isa=${levels[i]}
    set +e
    report=$(JTRACER_EMBREE_CONFIG="verbose=1,isa=$isa" "$cli" "${scenes[0]}" -q \
        -o "$work/probe.bmp" --width 8 --height 8 2>&1)
    code=$?
    set -e
    if [ $code -ne 0 ]; then
        grep -q "cannot start Embree with JTRACER_EMBREE_CONFIG='verbose=1,isa=$isa'" <<<"$report" ||
            fail "isa=$isa: unexpected failure: $report"
        echo "isa=$isa: not supported by this CPU, left out"
        continue
    fi
    chosen=$(grep -A3 '^  Config' <<<"$report" | grep 'ISA' | head -1)
    want=$(tr a-z A-Z <<<"$isa")
    grep -qw -- "${want}" <<<"$chosen" || fail "isa=$isa not applied: '$chosen'"
    if ((i + 1 < ${#levels[@]})); then
        above=$(tr a-z A-Z <<<"${levels[i + 1]}")
        ! grep -qw -- "$above" <<<"$chosen" || fail "isa=$isa still allows $above: '$chosen'"
    fi
    isas+=("$isa")
done
[ ${#isas[@]} -ge 2 ] || fail "fewer than two ISAs to compare: ${isas[*]}"

sums=$work/sums
: >"$sums"
for scene in "${scenes[@]}"; do
    name=${scene#"$source_dir/"}
    name=${name#"$work/"}
    env -u JTRACER_EMBREE_CONFIG "$cli" "$scene" -q -o "$work/default.bmp" \
        --width 256 --height 144 || fail "$name: render failed"
    for isa in "${isas[@]}"; do
        JTRACER_EMBREE_CONFIG="isa=$isa" "$cli" "$scene" -q -o "$work/$isa.bmp" \
            --width 256 --height 144 || fail "$name isa=$isa: render failed"
        cmp -s "$work/default.bmp" "$work/$isa.bmp" ||
            fail "$name: isa=$isa gives other bytes than Embree's default"
    done
    # libjpeg-turbo picks its vector unit too (JPEG image maps): its plain C code.
    JSIMD_FORCENONE=1 "$cli" "$scene" -q -o "$work/no-simd.bmp" --width 256 --height 144 ||
        fail "$name JSIMD_FORCENONE=1: render failed"
    cmp -s "$work/default.bmp" "$work/no-simd.bmp" ||
        fail "$name: libjpeg-turbo without SIMD gives other bytes"
    echo "$(md5sum <"$work/default.bmp" | cut -d' ' -f1) $name" >>"$sums"
done
echo "isa identity: ${#scenes[@]} scenes byte-identical with isa=${isas[*]} and the default"

# Across builds of the same revision.
version=$("$cli" --version)
mkdir -p "$sums_dir"
{
    echo "$version"
    sort -k2 "$sums"
} >"$sums_dir/$build.sums.tmp"
mv "$sums_dir/$build.sums.tmp" "$sums_dir/$build.sums"
compared=0
for other in "$sums_dir"/*.sums; do
    [ "$other" != "$sums_dir/$build.sums" ] || continue
    [ "$(head -1 "$other")" = "$version" ] || continue
    diff "$other" "$sums_dir/$build.sums" >/dev/null ||
        fail "the $build build's images differ from $(basename "$other" .sums)'s: $(diff "$other" "$sums_dir/$build.sums" | head -4)"
    echo "isa identity: the $build build gives the same bytes as $(basename "$other" .sums)"
    compared=$((compared + 1))
done
[ $compared -gt 0 ] || echo "isa identity: no other build of $version to compare with yet"

#!/usr/bin/env bash
# The image must not depend on which vector unit Embree or JTracer picks, nor
# on how JTracer was built. Renders every scene in scenes/ (not the parts/
# that scenes include) and BVH-sized scenes from
# the bench generator (thousands of overlapping spheres and cylinders) with
# the default choices and forced to each ISA this CPU runs: Embree's by
# JTRACER_EMBREE_CONFIG=isa=..., JTracer's own batched tests by
# JTRACER_SIMD (sse2 below AVX, avx from it); and with libjpeg-turbo's SIMD
# code off (JSIMD_FORCENONE=1), and requires identical bytes. It prints the CPU's
# features, the target Embree's default takes and each level it compared. The sums are
# kept in SUMS_DIR/BUILD.sums and compared with those of the other builds of
# the same revision (release, debug, sanitizers) found there.
# Usage: isa_identity_test.sh CLI SOURCE_DIR SUMS_DIR BUILD [--builds-only]
# --builds-only renders each scene once, with Embree's default, and only
# compares with the other builds: Embree's kernels are the same library in
# every build, so one build (release) checking each ISA covers them, and the
# debug and sanitizer builds, many times slower, check only their own code.
set -euo pipefail
cli=$1 source_dir=$2 sums_dir=$3 build=$4 builds_only=${5:-}
[ -z "$builds_only" ] || [ "$builds_only" = --builds-only ] || {
    echo "usage: $0 CLI SOURCE_DIR SUMS_DIR BUILD [--builds-only]" >&2
    exit 2
}
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
    find "$source_dir/scenes" "$work/generated" -name '*.jts' -not -path '*/parts/*' | sort)
[ ${#scenes[@]} -ge 10 ] || fail "only ${#scenes[@]} scenes found"

# Embree's report of a device: the CPU features it enables (the ISA line under
# Config) and the code paths it may take, the highest last (Targets).
probe() {
    JTRACER_EMBREE_CONFIG="verbose=1${1:+,isa=$1}" "$cli" "${scenes[0]}" -q \
        -o "$work/probe.bmp" --width 8 --height 8 2>&1
}
config_line() { # FIELD REPORT
    grep -A4 '^  Config' <<<"$2" | grep -m1 "^ *$1 *:" | sed 's/^[^:]*: *//; s/ *(supported)//; s/ *$//'
}
highest_target() { # REPORT
    config_line Targets "$1" | awk '{print $NF}'
}

default_report=$(probe "") || fail "Embree's default does not start: $default_report"
default_target=$(highest_target "$default_report")
default_targets=" $(config_line Targets "$default_report") "
[ -n "$default_target" ] || fail "no Targets line in Embree's report: $default_report"

# JTracer's own vector unit for each Embree level: SSE2 below AVX.
simd_for() { # ISA
    case $1 in sse2 | sse4.2) echo sse2 ;; *) echo avx ;; esac
}
# What `info` says JTracer's batched tests run on, with JTRACER_SIMD=VALUE or
# (no argument) unset.
vector_unit() { # [VALUE]
    if [ $# -eq 0 ]; then
        env -u JTRACER_SIMD "$cli" info --json "${scenes[0]}"
    else
        JTRACER_SIMD=$1 "$cli" info --json "${scenes[0]}"
    fi | python3 -c 'import json, sys; print(json.load(sys.stdin)["vector_unit"])'
}

# Each level Embree can be forced to, and the highest target it must then
# take. Embree names its AVX-512 target AVX512 (3.13) or AVX512SKX/AVX512KNL
# (older), and its ISA line lists AVX512F, AVX512DQ, ...: the targets, not the
# feature names, say which code runs. A level Embree runs by default on this
# CPU must also run when forced; only a level above the CPU's is left out.
levels=(sse2 sse4.2 avx avx2 avx512)
targets=(SSE2 SSE4.2 AVX AVX2 'AVX512[A-Z]*')
[ -z "$builds_only" ] || levels=()
isas=()
compared=()
left_out=()
for i in "${!levels[@]}"; do
    isa=${levels[i]} target=${targets[i]}
    set +e
    report=$(probe "$isa")
    code=$?
    set -e
    if [ $code -ne 0 ]; then
        grep -q "cannot start Embree with JTRACER_EMBREE_CONFIG='verbose=1,isa=$isa'" <<<"$report" ||
            fail "isa=$isa: unexpected failure: $report"
        ! grep -qE " ($target) " <<<"$default_targets" ||
            fail "isa=$isa refused, though Embree's default runs its target here ($default_targets)"
        echo "isa=$isa: not supported by this CPU, left out"
        left_out+=("$isa")
        continue
    fi
    chosen=$(highest_target "$report")
    grep -qxE -- "$target" <<<"$chosen" ||
        fail "isa=$isa not applied: its highest target is '$chosen', not $target (Targets: $(config_line Targets "$report"))"
    isas+=("$isa")
    compared+=("isa=$isa ($chosen, JTracer's $(simd_for "$isa"))")
done
[ -n "$builds_only" ] || [ ${#isas[@]} -ge 2 ] || fail "fewer than two ISAs to compare: ${isas[*]}"

if [ -z "$builds_only" ]; then
    cpu_avx=sse2
    grep -qw avx /proc/cpuinfo && cpu_avx=avx
    chosen=$(vector_unit)
    [ "$chosen" = "$cpu_avx" ] || fail "JTracer's default vector unit is $chosen on a CPU with $cpu_avx"
    for simd in sse2 ${cpu_avx/sse2/}; do
        chosen=$(vector_unit "$simd")
        [ "$chosen" = "$simd" ] || fail "JTRACER_SIMD=$simd not applied: info says $chosen"
    done
    if JTRACER_SIMD=avx512 "$cli" "${scenes[0]}" -q -o "$work/refused.bmp" 2>"$work/refused.txt"; then
        fail "JTRACER_SIMD=avx512 was accepted"
    fi
    grep -q "JTRACER_SIMD='avx512': expected sse2 or avx" "$work/refused.txt" ||
        fail "JTRACER_SIMD=avx512 refused without saying why: $(cat "$work/refused.txt")"
    [ ! -e "$work/refused.bmp" ] || fail "JTRACER_SIMD=avx512 left an image behind"
    echo "isa identity: JTracer's default vector unit here is $cpu_avx; JTRACER_SIMD applied"
fi
echo "isa identity: this CPU: $(config_line ISA "$default_report")"
echo "isa identity: Embree's default takes $default_target; compared with ${compared[*]}"

sums=$work/sums
: >"$sums"
for scene in "${scenes[@]}"; do
    name=${scene#"$source_dir/"}
    name=${name#"$work/"}
    env -u JTRACER_EMBREE_CONFIG -u JTRACER_SIMD "$cli" "$scene" -q -o "$work/default.bmp" \
        --width 256 --height 144 || fail "$name: render failed"
    for isa in "${isas[@]}"; do
        simd=$(simd_for "$isa")
        JTRACER_EMBREE_CONFIG="isa=$isa" JTRACER_SIMD=$simd "$cli" "$scene" -q \
            -o "$work/$isa.bmp" --width 256 --height 144 ||
            fail "$name isa=$isa JTRACER_SIMD=$simd: render failed"
        cmp -s "$work/default.bmp" "$work/$isa.bmp" ||
            fail "$name: isa=$isa JTRACER_SIMD=$simd gives other bytes than the defaults"
    done
    # libjpeg-turbo picks its vector unit too (JPEG image maps): its plain C code.
    [ -z "$builds_only" ] || {
        echo "$(md5sum <"$work/default.bmp" | cut -d' ' -f1) $name" >>"$sums"
        continue
    }
    JSIMD_FORCENONE=1 "$cli" "$scene" -q -o "$work/no-simd.bmp" --width 256 --height 144 ||
        fail "$name JSIMD_FORCENONE=1: render failed"
    cmp -s "$work/default.bmp" "$work/no-simd.bmp" ||
        fail "$name: libjpeg-turbo without SIMD gives other bytes"
    echo "$(md5sum <"$work/default.bmp" | cut -d' ' -f1) $name" >>"$sums"
done
if [ -n "$builds_only" ]; then
    echo "isa identity: ${#scenes[@]} scenes rendered with Embree's default ($default_target) only"
else
    echo "isa identity: ${#scenes[@]} scenes byte-identical with Embree's default ($default_target) and ${compared[*]}${left_out[*]:+; left out (above this CPU): ${left_out[*]}}"
fi

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

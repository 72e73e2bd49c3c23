#!/usr/bin/env bash
# How jtracer-mpi scales on this machine, and what that predicts for a farm.
#
#   bench/mpi/scaling.sh [BUILD_DIR] [WIDTH HEIGHT SAMPLES [REPEATS [TILE]]]
#
# Renders scenes/showcase.jts (default 1920x1080, 4 samples, 128-pixel tiles)
# with 1, 2 and 4 ranks, first at 1 thread a rank (a fair curve on few cores),
# then at 2 threads a rank, REPEATS times each (default 3), and prints the
# median wall time, the speed-up over 1 rank x 1 thread, and where rank 0's
# coordinating thread spent the render: waiting (idle, so it has headroom) and
# merging (receiving and pasting tiles). Every image is checked against
# jtracer-cli's, byte for byte. It ends with an estimate for 16 and 64 machines
# at 7680x4320 from the measured cost of a tile and the size of its message.
set -euo pipefail
root=$(cd "$(dirname "$0")/../.." && pwd)
build=${1:-$root/build/release}
width=${2:-1920}
height=${3:-1080}
samples=${4:-4}
repeats=${5:-3}
tile=${6:-128}
mpi=$build/mpi/jtracer-mpi
cli=$build/cli/jtracer-cli
scene=$root/scenes/showcase.jts
for program in "$mpi" "$cli"; do
    [ -x "$program" ] || { echo "scaling.sh: $program is not built" >&2; exit 1; }
done
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
settings=(--width "$width" --height "$height" --samples "$samples")

"$cli" "$scene" "${settings[@]}" -q -o "$work/cli.bmp"
median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

echo "showcase.jts ${width}x${height}, $samples samples, ${tile}x${tile} tiles, median of $repeats runs, $(nproc) cores"
printf '%-6s %-8s %8s %8s %8s %9s %10s %13s %8s\n' ranks threads "wall s" "loop s" speedup "r0 wait%" "r0 merge%" "ms/tile/rank" "MB recv"
base=""
for threads in 1 2; do
    for ranks in 1 2 4; do
        : > "$work/runs"
        for ((i = 0; i < repeats; i++)); do
            start=$(date +%s.%N)
            mpirun --oversubscribe --allow-run-as-root -np "$ranks" "$mpi" "$scene" "${settings[@]}" \
                --threads "$threads" --tile-size "$tile" -q --stats -o "$work/mpi.bmp" 2> "$work/stats"
            cmp -s "$work/mpi.bmp" "$work/cli.bmp" || { echo "scaling.sh: $ranks ranks differ from jtracer-cli" >&2; exit 1; }
            end=$(date +%s.%N)
            {
                awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f ", b - a }'
                sed -n 's/.*, \([0-9.]*\) s rendering loop.*/\1/p' "$work/stats" | tr '\n' ' '
                sed -n 's/.*waiting [0-9.]* s (\([0-9.]*\)%).*/\1/p' "$work/stats" | tr '\n' ' '
                sed -n 's/.*merging [0-9.]* s (\([0-9.]*\)%).*/\1/p' "$work/stats" | tr '\n' ' '
                sed -n 's/.*(\([0-9.]*\) ms a tile).*/\1/p' "$work/stats" |
                    awk '$1 > 0 { s += $1; n++ } END { printf "%.2f ", s / n }'
                sed -n 's/.* \([0-9.]*\) MB received.*/\1/p' "$work/stats"
            } >> "$work/runs"
        done
        # The run with the median rendering loop (mpirun's start-up, about a
        # second here, is in "wall s" but not in the speed-up).
        loop=$(cut -d' ' -f2 "$work/runs" | median)
        line=$(awk -v l="$loop" '$2 == l' "$work/runs" | head -1)
        [ -n "$base" ] || base=$loop
        set -- $line
        printf '%-6s %-8s %8.3f %8.3f %8.2f %9s %10s %13s %8s\n' "$ranks" "$threads" "$1" "$2" \
            "$(awk -v b="$base" -v l="$loop" 'BEGIN { print b / l }')" "$3" "$4" "$5" "$6"
        [ "$ranks$threads" = 11 ] && cp "$work/stats" "$work/stats11"
        [ "$ranks$threads" = 41 ] && cp "$work/stats" "$work/stats41"
    done
done

# The farm estimate, from the 1 rank x 1 thread run: a tile's cost on one core
# and the coordinator's merge cost a tile; a tile message is its RGB bytes plus
# a 24-byte header.
tile_ms=$(sed -n 's/.*rank 0: .*(\([0-9.]*\) ms a tile).*/\1/p' "$work/stats11")
setup_s=$(sed -n 's/.*rank 0: .*setup \([0-9.]*\) s.*/\1/p' "$work/stats11")
# rank 0's merge cost a received tile, from the 4-rank run
merge_ms=$(sed -n 's/.*merging \([0-9.]*\) s .*, \([0-9]*\) tiles and .*/\1 \2/p' "$work/stats41" |
    awk '{ printf "%.4f", ($2 > 0 ? 1000 * $1 / $2 : 0) }')
echo
echo "Estimate for 7680x4320, $samples samples, ${tile}x${tile} tiles: ${tile_ms} ms a tile on one core,"
echo "  ${merge_ms} ms for rank 0 to take in a tile, ${setup_s} s to read and prepare the scene (all measured here)"
awk -v ms="$tile_ms" -v merge="$merge_ms" -v setup="$setup_s" -v t="$tile" -v w=7680 -v h=4320 -v pw="$width" -v ph="$height" 'BEGIN {
    tiles = int((w + t - 1) / t) * int((h + t - 1) / t)
    bytes = t * t * 3 + 24
    total_core_s = tiles * ms / 1000
    printf "  %d tiles, %.1f KB a message, %.1f MB in all; %.0f core-seconds of rendering\n",
           tiles, bytes / 1000, tiles * bytes / 1e6, total_core_s
    printf "  %-9s %-6s %12s %14s %14s %14s\n", "machines", "cores", "render s", "1 Gbit/s s", "10 Gbit/s s", "speed-up"
    n = split("16 64", machines, " ")
    for (i = 1; i <= n; i++) {
        m = machines[i]
        for (c = 16; c <= 64; c *= 4) {
            # The slowest of: the rendering itself (plus the last tile), rank
            # 0 link (90% of the line rate), rank 0 taking in every tile.
            # Latency hides: every worker is kept two tiles ahead.
            render = total_core_s / (m * c) + ms / c / 1000
            link1 = tiles * bytes * 8 / 1e9 / 0.9
            link10 = link1 / 10
            intake = tiles * merge / 1000
            t1 = (render > link1 ? render : link1); t1 = (t1 > intake ? t1 : intake)
            t10 = (render > link10 ? render : link10); t10 = (t10 > intake ? t10 : intake)
            one = total_core_s / c + setup
            printf "  %-9d %-6d %12.2f %14.2f %14.2f %6.0fx / %3.0fx\n", m, c, render, link1, link10,
                   one / (t1 + setup), one / (t10 + setup)
        }
    }
}'
echo "  (render s: tiles spread over every core; Gbit/s columns: the time rank 0's link needs for all"
echo "   the pixels; speed-up over one such machine, at 1 and at 10 Gbit/s, setup included)"

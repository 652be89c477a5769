#!/usr/bin/env bash
# Renders the same scenes with POV-Ray 3.7 and with `strahl bench`, at the same size, in the same
# run, and prints a Markdown table: ms per frame, Mrays/s and strahl's speed-up over POV-Ray, for
# each accelerator (bvh, grid, none), packets on/off and 1 and 2 threads.
#
#   scripts/compare_povray.sh [> docs/perf/compare-$(date +%F).md]
#
# Environment: W, H (1280x720), REPEATS (POV-Ray runs per cell, median; 3), FRAMES (strahl timed
# frames per cell, median; 5), MANY (objects in the generated scene; 10000), NONE_MAX (brute force
# is skipped above this many objects; 2000), THREADS ("1 2").
#
# POV-Ray is timed by its own "Trace Time" (parsing and bounding excluded, as strahl bench excludes
# them), with -A (no antialiasing) and no output file. Its ray count is its "Rays" plus "Shadow Ray
# Tests", which is what strahl counts as primary + reflected + shadow rays.
set -euo pipefail

W=${W:-1280}
H=${H:-720}
REPEATS=${REPEATS:-3}
FRAMES=${FRAMES:-5}
MANY=${MANY:-10000}
NONE_MAX=${NONE_MAX:-2000}
THREADS=${THREADS:-"1 2"}
POV_INCLUDE=/usr/share/povray-3.7/include

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

if ! command -v povray >/dev/null 2>&1; then
    echo "compare_povray.sh: povray not found on PATH; skipping the comparison."
    exit 0
fi

cargo build --release --quiet --bin strahl
strahl=$root/target/release/strahl
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

"$strahl" gen spheres "$MANY" -o "$tmp/many_spheres_$MANY.pov"
scenes=("scenes/seed.pov:0" "$tmp/many_spheres_$MANY.pov:$MANY")

median() { sort -g | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }

# Prints "ms mrays" for one POV-Ray configuration: median trace time over REPEATS runs.
povray_cell() {
    local scene=$1 threads=$2 times=() log rays shadow secs
    for _ in $(seq "$REPEATS"); do
        log=$(povray +I"$scene" +W"$W" +H"$H" -D -A -F +WT"$threads" +L"$POV_INCLUDE" 2>&1 || true)
        secs=$(echo "$log" | sed -n 's/.*Trace Time:.*(\s*\([0-9.]*\) seconds).*/\1/p' | head -1)
        rays=$(echo "$log" | sed -n 's/^Rays:\s*\([0-9]*\).*/\1/p' | head -1)
        shadow=$(echo "$log" | sed -n 's/^Shadow Ray Tests:\s*\([0-9]*\).*/\1/p' | head -1)
        if [[ -z "$secs" ]]; then
            echo "povray failed on $scene:" >&2
            echo "$log" | tail -20 >&2
            exit 1
        fi
        times+=("$secs")
    done
    secs=$(printf '%s\n' "${times[@]}" | median)
    awk -v s="$secs" -v r="${rays:-0}" -v sh="${shadow:-0}" 'BEGIN { printf "%.1f %.2f\n", s * 1000, (r + sh) / s / 1e6 }'
}

# Prints "ms mrays" for one strahl configuration (bench's median frame).
strahl_cell() {
    local scene=$1 threads=$2 accel=$3 packets=$4 json=$tmp/bench.json extra=()
    [[ $packets == off ]] && extra=(--no-packets)
    "$strahl" bench "$scene" -W "$W" -H "$H" --frames "$FRAMES" --warmup 1 --threads "$threads" \
        --accel "$accel" "${extra[@]}" --json "$json" >/dev/null
    awk '/"median_ms"/ { gsub(/[,]/, ""); ms = $2 } /"mrays_per_s"/ && !m { gsub(/[,]/, ""); m = $2 }
         END { printf "%.1f %.2f\n", ms, m }' "$json"
}

echo "# strahl vs POV-Ray 3.7 — $(date +%F)"
echo
echo "- machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //'), $(nproc) cores (shared, noisy)"
echo "- POV-Ray: $(povray --version 2>&1 | grep -m1 'POV-Ray' || echo unknown)"
echo "- strahl: $(git rev-parse --short HEAD) ($(git rev-parse --abbrev-ref HEAD))"
echo "- ${W}x${H}, no antialiasing; POV-Ray: median Trace Time of $REPEATS runs; strahl bench: median of $FRAMES frames after 1 warm-up"
echo "- Mrays/s counts primary + reflected + shadow rays for both; speed-up = POV-Ray ms / strahl ms at the same thread count"
echo "- packets apply to the BVH only (grid and none always trace single rays)"
echo
for entry in "${scenes[@]}"; do
    scene=${entry%%:*}
    n=${entry##*:}
    echo "## $(basename "$scene")"
    echo
    echo "| renderer | accel | packets | threads | ms/frame | Mrays/s | speed-up |"
    echo "|---|---|---|---|---:|---:|---:|"
    for t in $THREADS; do
        read -r pov_ms pov_mr < <(povray_cell "$scene" "$t")
        echo "| POV-Ray 3.7 | (own) | - | $t | $pov_ms | $pov_mr | 1.00 |"
        for mode in bvh:on bvh:off grid:off none:off; do
            accel=${mode%%:*}
            packets=${mode##*:}
            if [[ $accel == none && $n -gt $NONE_MAX ]]; then
                echo "| strahl | none | off | $t | skipped ($n objects > NONE_MAX=$NONE_MAX) | | |"
                continue
            fi
            read -r ms mr < <(strahl_cell "$scene" "$t" "$accel" "$packets")
            speedup=$(awk -v a="$pov_ms" -v b="$ms" 'BEGIN { printf "%.2f", a / b }')
            echo "| strahl | $accel | $packets | $t | $ms | $mr | $speedup |"
        done
    done
    echo
done

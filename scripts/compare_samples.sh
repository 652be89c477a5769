#!/usr/bin/env bash
# Times every scene of the sample suite (tests/samples/scenes.txt) in POV-Ray 3.7 and in strahl
# in the same run, and flies an orbit of each in the window, then writes a Markdown table:
#
#   scripts/compare_samples.sh            # writes docs/perf/samples-$(date +%F).md
#   OUT=/tmp/t.md scripts/compare_samples.sh
#
# Per scene, from a temporary copy of the scene's folder (scenes write files, e.g. fileio.pov):
#   - POV-Ray 3.7: +W640 +H480 -A -D -V -F, all cores; its "Trace Time" (parse and bounding
#     excluded), median of REPEATS runs;
#   - strahl bench at 640x480 on the scene's camera, all cores: median of FRAMES frames after one
#     warm-up (render() only, as POV-Ray's trace time excludes parsing);
#   - the ratio POV-Ray ms / strahl ms (how many times faster strahl is);
#   - `strahl path orbit` (ORBIT_SECONDS per turn), then `xvfb-run strahl view SCENE --path P
#     --report R` at 640x480 (adaptive resolution, target 60 fps): the window's median presented
#     frame rate (1000 / median frame interval) and mean render scale.
# The seed scene (scenes/seed.pov) is measured the same way in the same run, for its ratio.
#
# Environment: SCENES (list file; tests/samples/scenes.txt), ROOT (/usr/share/povray-3.7/scenes),
# REPEATS (1), FRAMES (5), ORBIT_SECONDS (5), VIEW (1; 0 skips the window), TIMEOUT (per
# command, seconds; 600), NOTE (a line for the machine's state), STRAHL (the binary; target/release/strahl if built, else
# target/quick/strahl), OUT (docs/perf/samples-DATE.md), ONLY (a grep pattern of scenes to run),
# BASE (a second strahl binary, e.g. the previous commit's: each scene is timed with it just
# before STRAHL, and the table gets its columns and a before/after summary).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

SCENES=${SCENES:-tests/samples/scenes.txt}
ROOT=${ROOT:-/usr/share/povray-3.7/scenes}
REPEATS=${REPEATS:-1}
FRAMES=${FRAMES:-5}
ORBIT_SECONDS=${ORBIT_SECONDS:-5}
VIEW=${VIEW:-1}
TIMEOUT=${TIMEOUT:-600}
ONLY=${ONLY:-.}
OUT=${OUT:-docs/perf/samples-$(date +%F).md}
POV_INCLUDE=/usr/share/povray-3.7/include
if [[ -z ${STRAHL:-} ]]; then
    if [[ -x target/release/strahl ]]; then STRAHL=$root/target/release/strahl; else STRAHL=$root/target/quick/strahl; fi
fi
[[ $STRAHL == /* ]] || STRAHL=$root/$STRAHL
BASE=${BASE:-}
[[ -z $BASE || $BASE == /* ]] || BASE=$root/$BASE
[[ -z $BASE || -x $BASE ]] || { echo "compare_samples.sh: no binary at BASE=$BASE" >&2; exit 1; }

if ! command -v povray >/dev/null 2>&1; then
    echo "compare_samples.sh: povray not found on PATH; nothing to compare with." >&2
    exit 1
fi
[[ -x $STRAHL ]] || { echo "compare_samples.sh: no strahl binary at $STRAHL (cargo build --profile quick)" >&2; exit 1; }
if [[ $VIEW == 1 ]] && ! command -v xvfb-run >/dev/null 2>&1; then
    echo "compare_samples.sh: xvfb-run not found; run with VIEW=0 to skip the window" >&2
    exit 1
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# median, json_num, povray_ms
source "$root/scripts/lib/compare.sh"

# One row: "| scene | povray ms | strahl ms | ratio | fps | scale | note |", with BASE
# "| scene | povray ms | base ms | base ratio | strahl ms | ratio | fps | scale | note |".
row() {
    local scene=$1 dir file pov ms ratio fps scale note="" base_cols=""
    dir=$work/scene
    rm -rf "$dir"
    mkdir -p "$dir"
    cp -r "$(dirname "$scene")"/. "$dir"/
    file=$(basename "$scene")
    pov=$(povray_ms "$dir" "$file")
    [[ -n $pov ]] || note="POV-Ray: $(cat "$work/why")"
    time_both "$dir" "$file" "$pov" 1
    fps=""
    scale=""
    if [[ $VIEW == 1 && -n $ms ]]; then
        rm -f "$work/orbit.path" "$work/report.json"
        if (cd "$dir" && timeout "$TIMEOUT" "$STRAHL" path orbit "$file" -o "$work/orbit.path" \
            --seconds "$ORBIT_SECONDS" -q 2>"$work/orbit.err") &&
            (cd "$dir" && timeout "$TIMEOUT" xvfb-run -a -s "-screen 0 1280x1024x24" "$STRAHL" view "$file" \
                -W 640 -H 480 --path "$work/orbit.path" --report "$work/report.json" >/dev/null 2>"$work/view.err"); then
            fps=$(sed -n '/"frame_time_ms"/,/}/p' "$work/report.json" | sed -n 's/.*"median": *\([0-9.eE+-]*\).*/\1/p' |
                head -1 | awk '{ if ($1 > 0) printf "%.1f", 1000 / $1 }')
            scale=$(sed -n '/"render_scale"/,/}/p' "$work/report.json" | sed -n 's/.*"mean": *\([0-9.eE+-]*\).*/\1/p' |
                head -1 | awk '{ printf "%.2f", $1 }')
        else
            note="${note:+$note; }view: $(grep -m1 -i error "$work/orbit.err" "$work/view.err" | cut -c1-80)"
        fi
    fi
    echo "| $2 | $pov |$base_cols $ms | $ratio | $fps | $scale | $note |"
}

commit=$(git rev-parse --short HEAD)
branch=$(git rev-parse --abbrev-ref HEAD)
dirty=$(git diff --quiet HEAD 2>/dev/null || echo " + uncommitted changes")
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
rows=$work/rows.md
: >"$rows"
seed_row=$(row "$root/scenes/seed.pov" "seed.pov (scenes/)")
while read -r scene; do
    [[ -z $scene || $scene == \#* ]] && continue
    echo "$scene" | grep -q -- "$ONLY" || continue
    echo "compare_samples: $scene" >&2
    row "$ROOT/$scene" "$scene" >>"$rows"
done <"$SCENES"

# The ratio's column (awk field): after the base's two columns when BASE is set.
rc=5
[[ -z $BASE ]] || rc=7
ratios=$(awk -F'|' -v c=$rc '$c ~ /[0-9]/ { print $c }' "$rows" | median)
fpss=$(awk -F'|' -v c=$((rc + 1)) '$c ~ /[0-9]/ { print $c }' "$rows" | median)
below=$(awk -F'|' -v c=$rc '$c ~ /[0-9]/ && $c + 0 < 10 { n++ } END { print n + 0 }' "$rows")
measured=$(awk -F'|' -v c=$rc '$c ~ /[0-9]/ { n++ } END { print n + 0 }' "$rows")
seed_ratio=$(echo "$seed_row" | awk -F'|' -v c=$rc '{ gsub(/ /, "", $c); print $c }')
# The worst scene (lowest ratio) of a ratio column, as "ratio× scene".
worst() { awk -F'|' -v c="$1" '$c ~ /[0-9]/ { gsub(/ /, "", $2); print $c + 0, $2 }' "$rows" | sort -g | head -1 | awk '{ print $1 "× " $2 }'; }
before=""
if [[ -n $BASE ]]; then
    base_median=$(awk -F'|' '$5 ~ /[0-9]/ { print $5 }' "$rows" | median)
    before="Before (BASE): median ${base_median:-n/a}×, worst $(worst 5); after: median ${ratios:-n/a}×, worst $(worst 7). "
fi

tmp_out=$OUT.tmp.$$
{
    echo "# strahl vs POV-Ray 3.7 on the sample suite — $(date +%F)"
    echo
    echo "- machine: $cpu, $(nproc) cores, shared (timings are noisy; ratios are from the same run, one scene after the other)${NOTE:+; $NOTE}"
    echo "- POV-Ray: $(povray --version 2>&1 | grep -m1 'POV-Ray' || echo unknown), +W640 +H480 -A -D -V, all cores; its Trace Time, median of $REPEATS run(s)"
    echo "- strahl: $commit ($branch$dirty), binary $STRAHL; \`bench\` 640x480 on the scene camera, all cores, median of $FRAMES frames after 1 warm-up"
    echo "- ratio: POV-Ray ms / strahl ms (higher is faster); window: \`strahl path orbit --seconds $ORBIT_SECONDS\` then \`xvfb-run strahl view --path --report\` at 640x480, target 60 fps: fps = 1000 / median frame interval, scale = mean adaptive render scale"
    echo "- generated by \`scripts/compare_samples.sh\`"
    echo
    [[ -z $BASE ]] || echo "- base: binary $BASE, timed just before strahl on each scene, in the same run"
    echo
    echo "**${before}Median ratio: ${ratios:-n/a}× over $measured scenes ($below below 10×); seed scene: ${seed_ratio:-n/a}× in the same run. Median window fps: ${fpss:-n/a}.**"
    echo
    if [[ -n $BASE ]]; then
        echo "| scene | POV-Ray ms | base ms | base ratio | strahl ms | ratio | window fps | scale | notes |"
        echo "|---|---:|---:|---:|---:|---:|---:|---:|---|"
    else
        echo "| scene | POV-Ray ms | strahl ms | ratio | window fps | scale | notes |"
        echo "|---|---:|---:|---:|---:|---:|---|"
    fi
    echo "$seed_row"
    cat "$rows"
} >"$tmp_out"
mv "$tmp_out" "$OUT"
echo "wrote $OUT" >&2

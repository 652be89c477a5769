#!/usr/bin/env bash
# The load benchmark (issue #42): how long strahl and POV-Ray 3.7 take to read and bound a scene
# of N objects, and how much memory they hold, on the same generated files in the same run.
#
#   scripts/compare_load.sh                       # 0.1 M and 1 M; writes docs/perf/load-$(date +%F).md
#   MAX=10000000 POV_MAX=1000000 scripts/compare_load.sh   # 10 M with strahl alone
#
# For each kind (spheres: `strahl gen spheres N`, N spheres on a floor; mesh2: `strahl gen mesh2
# N`, one mesh2 sheet of N triangles) and each count N up to MAX, the file is generated once and
# rendered at 160x120, one sample per pixel, all cores, nothing else running from this script:
#   - strahl render -W 160 -H 120: its own statistics give Parse Time (reading the file, the
#     scene description), Build Time (render data and the BVH) and Trace Time;
#   - povray +W160 +H120 -D -A +WT2: its Parse Time, Bounding Time and Trace Time;
#   - both under /usr/bin/time -v: peak memory is its "Maximum resident set size".
# Ratios are strahl / POV-Ray: below 1 strahl is faster or smaller. "load" is parse + build
# (strahl) against parse + bounding (POV-Ray).
#
# Environment: COUNTS (space-separated; "100000 1000000 10000000"), KINDS ("spheres mesh2"), MAX
# (counts above it are skipped; 1000000, since 10 M files take minutes and POV-Ray about 10 GB),
# POV_MAX (POV-Ray runs only up to this count; MAX), NORMALS (1: mesh2 with normal_vectors),
# STRAHL (the binary; target/release/strahl), BASE (a second strahl binary, e.g. main's: its
# row is measured on the same file just before STRAHL's), THREADS (POV-Ray +WT; 2), WORK (folder
# for the generated files, removed after each count; /tmp/strahl-load), TIMEOUT (per command,
# seconds; 3600), LIMIT_GB (address-space cap for each render, `ulimit -v`, so that a run that
# outgrows the machine fails alone instead of waking the OOM killer; 16), NOTE (a line about the
# machine's state), OUT (docs/perf/load-DATE.md).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

COUNTS=${COUNTS:-100000 1000000 10000000}
KINDS=${KINDS:-spheres mesh2}
MAX=${MAX:-1000000}
POV_MAX=${POV_MAX:-$MAX}
NORMALS=${NORMALS:-0}
THREADS=${THREADS:-2}
WORK=${WORK:-/tmp/strahl-load}
TIMEOUT=${TIMEOUT:-3600}
LIMIT_GB=${LIMIT_GB:-16}
NOTE=${NOTE:-}
OUT=${OUT:-docs/perf/load-$(date +%F).md}
STRAHL=${STRAHL:-$root/target/release/strahl}
BASE=${BASE:-}
[[ $STRAHL == /* ]] || STRAHL=$root/$STRAHL
[[ -z $BASE || $BASE == /* ]] || BASE=$root/$BASE
[[ $OUT == /* ]] || OUT=$root/$OUT
[[ -x $STRAHL ]] || { echo "compare_load.sh: no strahl binary at $STRAHL (cargo build --release)" >&2; exit 1; }
[[ -z $BASE || -x $BASE ]] || { echo "compare_load.sh: no binary at BASE=$BASE" >&2; exit 1; }
[[ -x /usr/bin/time ]] || { echo "compare_load.sh: /usr/bin/time not found (apt-get install time)" >&2; exit 1; }
have_povray=1
command -v povray >/dev/null 2>&1 || have_povray=0
mkdir -p "$WORK"

# "Key: ... (1.234 seconds)" (POV-Ray) or "Key:   1.234 s" (strahl) from log $1, in seconds.
seconds() {
    sed -n "s/^ *$2: .*(\s*\([0-9.]*\) seconds).*/\1/p; s/^$2: *\([0-9.]*\) s$/\1/p" "$1" | head -1
}
# Peak resident memory in MB from a /usr/bin/time -v log.
peak_mb() { sed -n 's/.*Maximum resident set size (kbytes): \([0-9]*\).*/\1/p' "$1" | awk '{ printf "%.0f", $1 / 1024 }'; }
# $1 / $2 to two places, or "–" when either is missing.
ratio() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b == "" || b + 0 == 0) print "–"; else printf "%.2f", a / b }'; }
sum() { awk -v a="$1" -v b="$2" 'BEGIN { if (a == "" || b == "") print ""; else printf "%.3f", a + b }'; }

# Runs binary $1 (strahl) on file $2; prints "parse build trace peak" or "fail reason".
run_strahl() {
    local log=$WORK/strahl.log
    if ! (ulimit -v $((LIMIT_GB * 1048576)) && timeout "$TIMEOUT" /usr/bin/time -v "$1" render -W 160 -H 120 "$2" -o "$WORK/strahl.png") >"$log" 2>&1; then
        echo "fail $(grep -m1 -iE 'error|memory|killed|signal' "$log" | cut -c1-60)"
        return
    fi
    echo "$(seconds "$log" 'Parse Time') $(seconds "$log" 'Build Time') $(seconds "$log" 'Trace Time') $(peak_mb "$log")"
}

run_povray() {
    local log=$WORK/povray.log
    if ! (ulimit -v $((LIMIT_GB * 1048576)) && timeout "$TIMEOUT" /usr/bin/time -v povray +I"$1" +W160 +H120 -D -A +WT"$THREADS" +O"$WORK/povray.png") >"$log" 2>&1; then
        echo "fail $(grep -m1 -iE 'error|memory|killed|signal' "$log" | cut -c1-60)"
        return
    fi
    echo "$(seconds "$log" 'Parse Time') $(seconds "$log" 'Bounding Time') $(seconds "$log" 'Trace Time') $(peak_mb "$log")"
}

# One table row: label, then "parse build trace peak" of strahl and of POV-Ray (or fail ...).
row() {
    local label=$1 s=($2) p=($3)
    if [[ ${s[0]} == fail ]]; then
        echo "| $label | ${s[*]:1} | | | | | | | | | | |"
        return
    fi
    [[ ${p[0]} == fail || ${p[0]} == - ]] && p=("" "" "" "")
    local sl pl
    sl=$(sum "${s[0]}" "${s[1]}")
    pl=$(sum "${p[0]:-}" "${p[1]:-}")
    echo "| $label | ${s[0]} | ${s[1]} | ${s[2]} | ${s[3]} | ${p[0]:-–} | ${p[1]:-–} | ${p[2]:-–} | ${p[3]:-–} | $(ratio "$sl" "$pl") | $(ratio "${s[3]}" "${p[3]:-}") | $(ratio "${s[2]}" "${p[2]:-}") |"
}

skipped=()
rows=()
for kind in $KINDS; do
    for n in $COUNTS; do
        if ((n > MAX)); then
            skipped+=("$kind $n")
            continue
        fi
        file=$WORK/$kind-$n.pov
        extra=()
        [[ $kind == mesh2 && $NORMALS == 1 ]] && extra=(--normals)
        "$STRAHL" gen "$kind" "$n" "${extra[@]}" -o "$file" >/dev/null
        size=$(du -m "$file" | cut -f1)
        echo "== $kind $n ($size MB)" >&2
        pov="- - - -"
        if ((have_povray && n <= POV_MAX)); then
            pov=$(run_povray "$file")
            echo "   povray: $pov" >&2
        fi
        if [[ -n $BASE ]]; then
            b=$(run_strahl "$BASE" "$file")
            echo "   base:   $b" >&2
            rows+=("$(row "$kind $n (base)" "$b" "$pov")")
        fi
        s=$(run_strahl "$STRAHL" "$file")
        echo "   strahl: $s" >&2
        rows+=("$(row "$kind $n, $size MB" "$s" "$pov")")
        rm -f "$file"
    done
done

{
    echo "# Load: parse, build and memory at 0.1 M to 10 M objects ($(date +%F))"
    echo
    echo "\`scripts/compare_load.sh\` (issue #42). $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'),"
    echo "$(nproc) cores, $(free -g | awk '/Mem:/ { print $2 }') GB. strahl: \`$(basename "$STRAHL") render -W 160 -H 120\`"
    echo "(all cores); POV-Ray 3.7: \`povray +W160 +H120 -D -A +WT$THREADS\`, on the same generated file."
    echo "Times in seconds from each program's own statistics; peak = maximum resident set size"
    echo "(\`/usr/bin/time -v\`), MB. load = strahl's parse + build / POV-Ray's parse + bounding;"
    echo "mem and trace are strahl / POV-Ray too (below 1: strahl is faster or smaller)."
    if ((${#skipped[@]})); then
        echo "Skipped (MAX=$MAX): ${skipped[*]}."
    fi
    if [[ $POV_MAX != "$MAX" ]]; then
        echo "POV-Ray ran only up to POV_MAX=$POV_MAX objects."
    fi
    [[ $NORMALS == 1 ]] && echo "mesh2 files carry normal_vectors (NORMALS=1)."
    [[ -n $NOTE ]] && echo "$NOTE"
    echo
    echo "| scene | strahl parse | build | trace | peak | POV-Ray parse | bounding | trace | peak | load | mem | trace |"
    echo "|---|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|--:|"
    printf '%s\n' "${rows[@]}"
} >"$OUT"
echo "wrote $OUT" >&2

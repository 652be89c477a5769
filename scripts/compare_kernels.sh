#!/usr/bin/env bash
# The kernel benchmark: times every scene of scenes/kernels/ (one shape kind each, an 8x8 grid on
# a floor, two point lights, one plain texture; the list and order are scenes/kernels/kernels.txt)
# in POV-Ray 3.7 and in strahl in the same run, and writes a Markdown table:
#
#   scripts/compare_kernels.sh            # writes docs/perf/kernels-$(date +%F).md
#   OUT=/tmp/k.md ONLY=lathe scripts/compare_kernels.sh
#
# Per scene, run in scenes/kernels/:
#   - POV-Ray 3.7: +W640 +H480 -A -D -V -F, all cores; its "Trace Time" (parse and bounding
#     excluded), median of REPEATS runs;
#   - strahl bench at 640x480, all cores: median of FRAMES frames after one warm-up (render()
#     only, as POV-Ray's trace time excludes parsing);
#   - the ratio POV-Ray ms / strahl ms (how many times faster strahl is);
#   - `strahl render` once at 640x480, for its statistics: tests/ray = the ray->shape tests of the
#     kind under test / all rays (primary + shadow + reflected + refracted); ns/test = strahl's
#     median frame time / those tests. The kind under test is every row of the statistics but
#     the floor's `Plane`, unless the scene names its rows in a `// stats: Row[, Row]` comment
#     (plane.pov: `Plane`). strahl counts a CSG node (intersection, difference, clipped_by, and a
#     merge it does not flatten) as one `CSG` test: its children's tests are inside it. ns/test
#     divides the whole frame (shading, the floor, shadow rays) by the kind's tests: an upper bound
#     on the kernel's cost per test;
#   - PSNR (dB, 8-bit RGB) of strahl's image against POV-Ray's (one more, untimed, POV-Ray render
#     with an output file; PSNR=0 skips it).
#
# Environment: SCENES (list file; scenes/kernels/kernels.txt), REPEATS (POV-Ray runs, median; 1),
# FRAMES (strahl timed frames, median; 5), PSNR (1), TIMEOUT (per command, seconds; 600), NOTE (a
# line for the machine's state), STRAHL (the binary; target/release/strahl if built, else
# target/quick/strahl), OUT (docs/perf/kernels-DATE.md), ONLY (a grep pattern of scenes to run),
# BASE (a second strahl binary, e.g. the previous commit's: each scene is timed with it just
# before STRAHL; the table gets its time and ratio and the summary a before/after line).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"

SCENES=${SCENES:-scenes/kernels/kernels.txt}
REPEATS=${REPEATS:-1}
FRAMES=${FRAMES:-5}
PSNR=${PSNR:-1}
TIMEOUT=${TIMEOUT:-600}
ONLY=${ONLY:-.}
OUT=${OUT:-docs/perf/kernels-$(date +%F).md}
POV_INCLUDE=/usr/share/povray-3.7/include
if [[ -z ${STRAHL:-} ]]; then
    if [[ -x target/release/strahl ]]; then STRAHL=$root/target/release/strahl; else STRAHL=$root/target/quick/strahl; fi
fi
[[ $STRAHL == /* ]] || STRAHL=$root/$STRAHL
BASE=${BASE:-}
[[ -z $BASE || $BASE == /* ]] || BASE=$root/$BASE
[[ -z $BASE || -x $BASE ]] || { echo "compare_kernels.sh: no binary at BASE=$BASE" >&2; exit 1; }
[[ $OUT == /* ]] || OUT=$root/$OUT

if ! command -v povray >/dev/null 2>&1; then
    echo "compare_kernels.sh: povray not found on PATH (apt-get install povray povray-includes fonts-povray)" >&2
    exit 1
fi
[[ -x $STRAHL ]] || { echo "compare_kernels.sh: no strahl binary at $STRAHL (cargo build --release)" >&2; exit 1; }
[[ $PSNR == 0 ]] || command -v python3 >/dev/null 2>&1 || { echo "compare_kernels.sh: python3 not found; run with PSNR=0" >&2; exit 1; }

dir=$(cd "$(dirname "$SCENES")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# median, json_num, povray_ms
source "$root/scripts/lib/compare.sh"

# PSNR in dB of two PNG files' 8-bit RGB (standard library only: zlib and the PNG filters).
cat >"$work/psnr.py" <<'EOF'
import math, struct, sys, zlib

def rgb(path):
    d = open(path, "rb").read()
    pos, idat = 8, b""
    while pos < len(d):
        n, = struct.unpack(">I", d[pos:pos + 4])
        kind, body = d[pos + 4:pos + 8], d[pos + 8:pos + 8 + n]
        pos += 12 + n
        if kind == b"IHDR":
            w, h, depth, ctype, _, _, interlace = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
    if depth not in (8, 16) or ctype not in (0, 2, 4, 6) or interlace:
        sys.exit(f"{path}: unsupported PNG (depth {depth}, colour type {ctype}, interlace {interlace})")
    ch = {0: 1, 2: 3, 4: 2, 6: 4}[ctype]
    bpp = ch * depth // 8
    stride = w * bpp
    raw = zlib.decompress(idat)
    out, prev, p = bytearray(), bytearray(stride), 0
    for _ in range(h):
        f, line = raw[p], bytearray(raw[p + 1:p + 1 + stride])
        p += 1 + stride
        for i in range(stride):
            a = line[i - bpp] if i >= bpp else 0
            b = prev[i]
            c = prev[i - bpp] if i >= bpp else 0
            if f == 1: line[i] = (line[i] + a) & 255
            elif f == 2: line[i] = (line[i] + b) & 255
            elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
            elif f == 4:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
        out += line
        prev = line
    px = out[::depth // 8]  # the high byte of 16-bit samples
    if ch < 3:
        return w, h, bytes(v for v in px[::ch] for _ in range(3))
    return w, h, bytes(v for i in range(0, len(px), ch) for v in px[i:i + 3])

(wa, ha, a), (wb, hb, b) = rgb(sys.argv[1]), rgb(sys.argv[2])
if (wa, ha) != (wb, hb):
    sys.exit(f"sizes differ: {wa}x{ha} and {wb}x{hb}")
mse = sum((x - y) * (x - y) for x, y in zip(a, b)) / len(a)
print("inf" if mse == 0 else f"{10 * math.log10(255 * 255 / mse):.1f}")
EOF


# The statistics rows of `strahl render` as "name<TAB>tests", one a line.
stat_rows() {
    sed -n '/^Ray->Shape/,/^Bounding nodes/p' "$1" | grep -v '^Ray->Shape\|^Bounding nodes\|^---' |
        awk '{ name = $1; for (i = 2; i <= NF - 3; i++) name = name " " $i; print name "\t" $(NF - 2) }'
}

# One row: "| kind | povray ms | strahl ms | ratio | tests/ray | ns/test | PSNR | counted | notes |".
row() {
    local file=$1 kind=${1%.pov} pov ms ratio rays tests rows tpr nspt psnr="" note="" base_cols=""
    pov=$(povray_ms "$dir" "$file")
    [[ -n $pov ]] || note="POV-Ray: $(cat "$work/why")"
    time_both "$dir" "$file" "$pov" 2
    tpr=""
    nspt=""
    rows=$(sed -n 's|^// *stats: *||p' "$dir/$file" | head -1)
    rm -f "$work/strahl.png"
    if (cd "$dir" && timeout "$TIMEOUT" "$STRAHL" render "$file" -W 640 -H 480 -o "$work/strahl.png" \
        >"$work/render.out" 2>"$work/render.err"); then
        rays=$(sed -n 's/^Rays: *\([0-9]*\).*/\1/p' "$work/render.out" | head -1)
        stat_rows "$work/render.out" >"$work/rows.tsv"
        if [[ -n $rows ]]; then
            tests=$(awk -F'\t' -v want="$rows" 'BEGIN { n = split(want, w, / *, */); for (i = 1; i <= n; i++) k[w[i]] = 1 }
                k[$1] { t += $2 } END { print t + 0 }' "$work/rows.tsv")
        else
            tests=$(awk -F'\t' '$1 != "Plane" { t += $2 } END { print t + 0 }' "$work/rows.tsv")
            rows=$(awk -F'\t' '$1 != "Plane" { printf "%s%s", (n++ ? ", " : ""), $1 }' "$work/rows.tsv")
        fi
        tpr=$(awk -v t="$tests" -v r="$rays" 'BEGIN { if (r > 0) printf "%.2f", t / r }')
        nspt=$(awk -v t="$tests" -v m="$ms" 'BEGIN { if (t > 0 && m != "") printf "%.1f", m * 1e6 / t }')
        if [[ $PSNR != 0 ]] &&
            (cd "$dir" && timeout "$TIMEOUT" povray +I"$file" +W640 +H480 -A -D -V +FN +O"$work/pov.png" \
                +L"$POV_INCLUDE" >/dev/null 2>&1) && [[ -f $work/pov.png ]]; then
            psnr=$(python3 "$work/psnr.py" "$work/strahl.png" "$work/pov.png" 2>&1 | tail -1 | cut -c1-60)
            rm -f "$work/pov.png"
        fi
        if grep -qi warning "$work/render.err"; then
            note="${note:+$note; }strahl: $(grep -m1 -i warning "$work/render.err" | cut -c1-80)"
        fi
    else
        note="${note:+$note; }strahl render: $(grep -m1 error "$work/render.err" | cut -c1-80)"
    fi
    echo "| $kind | $pov | $ms | $ratio | $tpr | $nspt | $psnr | $rows |$base_cols $note |"
}

commit=$(git rev-parse --short HEAD)
branch=$(git rev-parse --abbrev-ref HEAD)
dirty=$(git diff --quiet HEAD 2>/dev/null || echo " + uncommitted changes")
# The commit the binary was built from, where it lies in a checkout's target/ folder.
bin_tree=$(cd "$(dirname "$STRAHL")" && git rev-parse --show-toplevel 2>/dev/null || true)
if [[ -n $bin_tree && $bin_tree != "$root" ]]; then
    bin_dirty=$(git -C "$bin_tree" diff --quiet HEAD 2>/dev/null || echo " + uncommitted changes")
    built="built from $(git -C "$bin_tree" rev-parse --short HEAD) in $bin_tree$bin_dirty"
else
    built="built from this checkout: $commit ($branch$dirty)"
fi
cpu=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')
rows=$work/rows.md
: >"$rows"
while read -r scene; do
    [[ -z $scene || $scene == \#* ]] && continue
    echo "$scene" | grep -q -- "$ONLY" || continue
    echo "compare_kernels: $scene" >&2
    row "$scene" >>"$rows"
done <"$SCENES"

ratios=$(awk -F'|' '$5 ~ /[0-9]/ { print $5 }' "$rows" | median)
measured=$(awk -F'|' '$5 ~ /[0-9]/ { n++ } END { print n + 0 }' "$rows")
worst=$(awk -F'|' '$5 ~ /[0-9]/ { gsub(/ /, "", $2); gsub(/ /, "", $5); print $5, $2 }' "$rows" | sort -g | head -1 |
    awk '{ if (NF) printf "%s (%s×)", $2, $1 }')
below=$(awk -F'|' '$5 ~ /[0-9]/ && $5 + 0 < 1 { gsub(/ /, "", $2); printf "%s%s", (n++ ? ", " : ""), $2 }' "$rows")
# Kinds at or above 5× and 10×, by a ratio column.
at_least() { awk -F'|' -v c="$1" -v k="$2" '$c ~ /[0-9]/ && $c + 0 >= k { n++ } END { print n + 0 }' "$rows"; }
counts="$(at_least 5 5) kinds at ≥ 5×, $(at_least 5 10) at ≥ 10×"
before=""
if [[ -n $BASE ]]; then
    base_median=$(awk -F'|' '$11 ~ /[0-9]/ { print $11 }' "$rows" | median)
    base_worst=$(awk -F'|' '$11 ~ /[0-9]/ { gsub(/ /, "", $2); gsub(/ /, "", $11); print $11, $2 }' "$rows" | sort -g |
        head -1 | awk '{ if (NF) printf "%s (%s×)", $2, $1 }')
    before="Before (BASE): median ${base_median:-n/a}×, worst ${base_worst:-n/a}, $(at_least 11 5) kinds at ≥ 5×, $(at_least 11 10) at ≥ 10×. After: "
fi

mkdir -p "$(dirname "$OUT")"
tmp_out=$OUT.tmp.$$
{
    echo "# Kernel benchmark: strahl vs POV-Ray 3.7, one shape kind per scene — $(date +%F)"
    echo
    echo "- machine: $cpu, $(nproc) cores${NOTE:+; $NOTE}"
    echo "- scenes: \`scenes/kernels/\` (list: \`$SCENES\`): an 8×8 grid of one kind on a floor plane, two point lights, one plain pigment with phong (\`kernel_common.inc\`); each scene's header says what it holds"
    echo "- POV-Ray: $(povray --version 2>&1 | grep -m1 'POV-Ray' || echo unknown), +W640 +H480 -A -D -V -F, all cores; its Trace Time, median of $REPEATS run(s)"
    echo "- strahl: binary $STRAHL, $built; \`bench -W 640 -H 480\`, all cores, median of $FRAMES frames after 1 warm-up; this checkout: $commit ($branch$dirty)"
    echo "- ratio: POV-Ray ms / strahl ms (higher: strahl faster)"
    echo "- tests/ray: strahl's ray→shape tests of the kind (the rows in \"counted\", from \`strahl render\`'s statistics; the floor's Plane row is left out) / all its rays (primary + shadow). A CSG node is one test (its children's tests are inside it); a union is flattened into its children, as is an opaque merge"
    echo "- ns/test: strahl's median **frame** time / those tests: the whole frame (floor, shading, shadow rays) per test of the kind, so an upper bound on the kernel's cost"
    echo "- PSNR: strahl's image against POV-Ray's, 8-bit RGB, dB"
    echo "- generated by \`scripts/compare_kernels.sh\`"
    echo
    [[ -z $BASE ]] || echo "- base: binary $BASE, timed just before strahl on each scene, in the same run"
    echo
    echo "**${before}Median ratio: ${ratios:-n/a}× over $measured kinds; worst: ${worst:-n/a}; $counts${below:+; slower than POV-Ray: $below}.**"
    echo
    if [[ -n $BASE ]]; then
        echo "| kind | POV-Ray ms | strahl ms | ratio | tests/ray | ns/test | PSNR dB | counted | base ms | base ratio | notes |"
        echo "|---|---:|---:|---:|---:|---:|---:|---|---:|---:|---|"
    else
        echo "| kind | POV-Ray ms | strahl ms | ratio | tests/ray | ns/test | PSNR dB | counted | notes |"
        echo "|---|---:|---:|---:|---:|---:|---:|---|---|"
    fi
    cat "$rows"
} >"$tmp_out"
mv "$tmp_out" "$OUT"
echo "wrote $OUT" >&2

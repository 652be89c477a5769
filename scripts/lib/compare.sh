# Shell functions shared by the comparison scripts (compare_samples.sh, compare_kernels.sh),
# sourced after they set POV_INCLUDE, REPEATS, TIMEOUT and `work` (a temporary folder).

# The median of the numbers on standard input, one a line.
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR) print v[int((NR + 1) / 2)]; else print "" }'; }

# A number from a JSON file: the first `"key": value` (top level keys come first in strahl's JSON).
json_num() { sed -n "s/.*\"$2\": *\([-0-9.eE+]*\).*/\1/p" "$1" | head -1; }

# POV-Ray's median trace time in ms of scene $2 in folder $1, or empty with the reason in $work/why.
povray_ms() {
    local dir=$1 file=$2 times=() log secs
    for _ in $(seq "$REPEATS"); do
        log=$(cd "$dir" && timeout "$TIMEOUT" povray +I"$file" +W640 +H480 -A -D -V -F +L"$POV_INCLUDE" 2>&1) || true
        secs=$(echo "$log" | sed -n 's/.*Trace Time:.*(\s*\([0-9.]*\) seconds).*/\1/p' | head -1)
        if [[ -z $secs ]]; then
            echo "$log" | grep -m1 -i "error" | cut -c1-80 >"$work/why" || echo "no trace time" >"$work/why"
            return
        fi
        times+=("$secs")
    done
    printf '%s\n' "${times[@]}" | median | awk '{ printf "%.1f", $1 * 1000 }'
}

# strahl's median frame in ms (bench at 640x480, FRAMES frames after one warm-up, all cores) of
# scene $3 in folder $2 with binary $1, printed with $4 decimals; empty with the first error line
# in $work/why_strahl.
strahl_ms() {
    local bin=$1 dir=$2 file=$3 digits=$4
    if (cd "$dir" && timeout "$TIMEOUT" "$bin" bench "$file" -W 640 -H 480 --frames "$FRAMES" --warmup 1 \
        --json "$work/bench.json" >/dev/null 2>"$work/bench.err"); then
        json_num "$work/bench.json" median_ms | awk -v d="$digits" '{ printf "%.*f", d, $1 }'
    else
        grep -m1 error "$work/bench.err" | cut -c1-80 >"$work/why_strahl" || echo "failed" >"$work/why_strahl"
    fi
}

# POV-Ray ms / strahl ms, or empty where either is missing.
ratio_of() {
    awk -v a="$1" -v b="$2" 'BEGIN { if (a != "" && b != "" && b > 0) printf (a / b >= 1 ? "%.1f" : "%.2g"), a / b }'
}

# Times scene $2 in folder $1 with BASE (when set) and then STRAHL, against POV-Ray's $3 ms,
# with $4 decimals: sets `ms`, `ratio` and `base_cols` (" base ms | base ratio |", or empty
# without BASE), and adds failures to `note`.
time_both() {
    local dir=$1 file=$2 pov=$3 digits=$4 base_ms
    base_cols=""
    if [[ -n ${BASE:-} ]]; then
        base_ms=$(strahl_ms "$BASE" "$dir" "$file" "$digits")
        [[ -n $base_ms ]] || note="${note:+$note; }base: $(cat "$work/why_strahl")"
        base_cols=" $base_ms | $(ratio_of "$pov" "$base_ms") |"
    fi
    ms=$(strahl_ms "$STRAHL" "$dir" "$file" "$digits")
    [[ -n $ms ]] || note="${note:+$note; }strahl: $(cat "$work/why_strahl")"
    ratio=$(ratio_of "$pov" "$ms")
}

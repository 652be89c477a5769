#!/bin/sh
# Parse time of POV-Ray 3.7 and of strahl on every sample scene strahl loads, from the scene's
# own folder as a user runs it. Usage: scripts/parse-times.sh [SAMPLES_DIR] [STRAHL_BINARY]
# Prints a Markdown table: scene, POV-Ray's "Parse Time", strahl's "Parse Time" (both in ms,
# each the median of 3 runs).
set -u
dir=${1:-/usr/share/povray-3.7/scenes}
strahl=$(realpath "${2:-target/release/strahl}")
command -v povray >/dev/null || { echo "povray is not installed (apt-get install povray)" >&2; exit 2; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
median() { sort -n | sed -n 2p; }
echo "| scene | POV-Ray parse ms | strahl parse ms |"
echo "|---|--:|--:|"
find "$dir" -name '*.pov' | sort | while read -r scene; do
  folder=$(dirname "$scene"); name=$(basename "$scene")
  ok=yes
  s=$(for i in 1 2 3; do
        (cd "$folder" && timeout 20 "$strahl" render "$name" -W 16 -H 12 -o "$tmp/s.png" 2>&1 </dev/null) \
          | sed -n 's/^Parse Time: *\([0-9.]*\) s$/\1/p'
      done | median)
  [ -n "$s" ] || ok=no
  [ "$ok" = yes ] || continue
  p=$(for i in 1 2 3; do
        (cd "$folder" && timeout 60 povray +I"$name" +O"$tmp/p.png" +W16 +H12 -D 2>&1 </dev/null) \
          | sed -n 's/.*Parse Time:.*(\([0-9.]*\) seconds).*/\1/p'
      done | median)
  printf '| %s | %s | %s |\n' "${scene#"$dir"/}" \
    "$(echo "${p:-nan}" | awk '{ printf "%.0f", $1 * 1000 }')" "$(echo "$s" | awk '{ printf "%.0f", $1 * 1000 }')"
done

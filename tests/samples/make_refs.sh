#!/bin/sh
# Regenerates the POV-Ray 3.7 renders that tests/suite/samples.rs compares strahl's against: every
# scene listed in scenes.txt beside this script, from Debian's povray-examples
# (/usr/share/povray-3.7/scenes), at 320x240 without antialiasing, into
# expected/<path with / as _>.png (objects/quartic/torus.pov -> objects_quartic_torus.png).
# Needs `povray`, `povray-includes` and `povray-examples`. Run from anywhere:
#   sh tests/samples/make_refs.sh [scene.pov ...]   (no arguments: every listed scene)
# Each scene renders from a temporary copy of its own folder (cwd there, as POV-Ray users run
# them: scenes include files beside them, and some write files, which the read-only install
# would refuse). No .ini is read, so the clock is 0 and animations render their first state.
set -eu
here=$(cd "$(dirname "$0")" && pwd)
samples=${POVRAY_SAMPLES:-/usr/share/povray-3.7/scenes}
inc=/usr/share/povray-3.7/include
out="$here/expected"
mkdir -p "$out"
if [ $# -gt 0 ]; then
    list=$*
else
    list=$(grep -v '^#' "$here/scenes.txt" | grep -v '^ *$')
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for s in $list; do
    name=$(echo "${s%.pov}" | tr / _)
    dir=$(dirname "$s")
    rm -rf "$tmp/scene"
    mkdir "$tmp/scene"
    cp -rL "$samples/$dir/." "$tmp/scene/"
    chmod -R u+w "$tmp/scene"
    (cd "$tmp/scene" && povray +I"$(basename "$s")" +O"$out/$name.png" +W320 +H240 -A -D -V +L"$inc" +FN \
        >"$tmp/log" 2>&1) || { cat "$tmp/log" >&2; echo "povray failed on $s" >&2; exit 1; }
    echo "wrote $out/$name.png"
done

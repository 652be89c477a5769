#!/bin/sh
# Writes tests/reference/scenes/hf.pgm, the height field of tests/reference/scenes/heightfields.pov:
# a 33×25 ASCII PGM (P2, maxval 255) of two hills and a ripple, deterministic (awk only).
# Usage: sh scripts/make-heightfield.sh [OUT.pgm]
set -eu
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-"$root/tests/reference/scenes/hf.pgm"}
awk 'BEGIN {
    w = 33; h = 25
    print "P2"; print "# strahl scripts/make-heightfield.sh"; print w, h; print 255
    for (j = 0; j < h; j++) {
        line = ""
        for (i = 0; i < w; i++) {
            x = i / (w - 1); z = j / (h - 1)
            v = 0.75 * exp(-((x - 0.3)^2 + (z - 0.35)^2) / 0.03) + 0.5 * exp(-((x - 0.72)^2 + (z - 0.65)^2) / 0.05)
            v += 0.08 * sin(14 * x) * cos(11 * z) + 0.1
            if (v < 0) v = 0
            if (v > 1) v = 1
            line = line (i ? " " : "") int(v * 255 + 0.5)
        }
        print line
    }
}' > "$out"
echo "wrote $out"

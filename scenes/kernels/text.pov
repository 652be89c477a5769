// Kernel benchmark: text, two glyphs ("Ag") of timrom.ttf (Debian's fonts-povray / POV-Ray's
// include folder), standing, 0.25 deep.
#version 3.7;
#include "kernel_common.inc"
KGrid(text { ttf "timrom.ttf" "Ag" 0.25, 0 scale 0.75 translate <-0.45, 0, -0.12> })

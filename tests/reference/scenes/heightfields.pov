// Height fields from hf.pgm (made by scripts/make-heightfield.sh): flat triangles, `smooth`,
// one cut off by `water_level` above a water plane, scaled, rotated and translated.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 5, -9>
    look_at <0, 0.5, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

height_field { pgm "hf.pgm"
    translate <-0.5, 0, -0.5> scale <3, 1.5, 3> translate <-2.2, 0, 1>
    pigment { color rgb <0.9, 0.5, 0.25> } }
height_field { pgm "hf.pgm" smooth
    translate <-0.5, 0, -0.5> scale <3, 1.5, 3> rotate y*30 translate <2.2, 0, 1>
    pigment { color rgb <0.3, 0.8, 0.35> } finish { phong 0.4 } }
height_field { pgm "hf.pgm" smooth water_level 0.3
    translate <-0.5, 0, -0.5> scale <2.5, 1.2, 2> translate <0, 0.2, -2.4>
    pigment { color rgb <0.7, 0.7, 0.95> } }
box { <-1.25, 0, -3.4>, <1.25, 0.52, -1.4> pigment { color rgb <0.2, 0.4, 0.9> } }

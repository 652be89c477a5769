// Tori: upright, tilted, thin and fat, one squashed by a non-uniform scale, one seen edge-on.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 5, -8>
    look_at <0, 0.8, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

torus { 1, 0.3 translate <-2.5, 0.3, 0> pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
torus { 0.8, 0.25 rotate x*70 translate <0, 1.2, 0.5> pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 } }
torus { 1.1, 0.06 sturm rotate z*20 translate <2.5, 1, 0> pigment { color rgb <0.3, 0.9, 0.3> } }
torus { 0.6, 0.45 scale <1, 0.5, 1.4> translate <1, 0.25, -2> pigment { color rgb <1, 0.8, 0.2> } }
torus { 0.7, 0.2 rotate x*90 rotate y*90 translate <-1.5, 0.9, -2.2> pigment { color rgb <0.8, 0.4, 1> } }

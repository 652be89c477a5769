// Surfaces of revolution: the documentation's open vase, a closed bottle with sturm, a tilted
// squat pot, and a bowl carved out of a box by a sor (inside test).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 4.5, -9>
    look_at <0, 1, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

sor { 7, <0.000000, 0.000000>, <0.118143, 0.000000>, <0.620253, 0.540084>, <0.210970, 0.827004>,
      <0.194093, 0.962025>, <0.286920, 1.000000>, <0.468354, 1.033755>
    open scale 2 translate <-3, 0, 1> pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
sor { 6, <0, -0.5>, <0.6, 0>, <0.7, 0.8>, <0.25, 1.6>, <0.3, 2.1>, <0.4, 2.5>
    sturm translate <-0.8, 0, 1.5> pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 } }
sor { 5, <0.5, -1>, <0.9, 0>, <1.1, 0.5>, <0.7, 1>, <0.5, 1.5>
    rotate z*25 translate <1.3, 0.4, 1.2> pigment { color rgb <0.3, 0.9, 0.3> } }
difference {
    box { <-0.9, 0, -0.9>, <0.9, 1.2, 0.9> }
    sor { 5, <0.2, -0.5>, <0.3, 0.3>, <0.8, 0.9>, <0.85, 1.4>, <0.9, 2> }
    rotate y*30 translate <3.4, 0, 0.5>
    pigment { color rgb <1, 0.8, 0.2> }
}

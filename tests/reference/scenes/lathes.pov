// Lathes: a linear goblet, a quadratic vase, a cubic bottle and a bezier bowl, one tilted.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 5, -9>
    look_at <0, 1, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

lathe { linear_spline 8, <0, 0>, <0.8, 0>, <0.8, 0.1>, <0.15, 0.2>, <0.15, 1.2>, <0.9, 1.8>, <0.8, 1.85>, <0, 1.3>
    translate <-3, 0, 1> pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
lathe { quadratic_spline 6, <0, -0.5>, <0, 0>, <0.9, 0.6>, <0.4, 1.5>, <0.6, 2>, <0, 2.2>
    translate <-1, 0, 1.5> pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 } }
lathe { cubic_spline 7, <0, -0.2>, <0, 0>, <0.7, 0.3>, <0.7, 1.2>, <0.25, 1.7>, <0, 2>, <0, 2.2>
    sturm translate <1.2, 0, 1.5> pigment { color rgb <0.3, 0.9, 0.3> } }
lathe { bezier_spline 8, <0, 0.6>, <0.6, 0.6>, <1.2, 0.6>, <1.2, 1.2>, <1.2, 1.2>, <1.0, 1.2>, <0.9, 0.8>, <0, 0.8>
    rotate z*20 translate <3, -0.3, 0> pigment { color rgb <1, 0.8, 0.2> } }

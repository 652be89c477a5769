// Julia fractals: quaternion sqr and cube (POV-Ray's documented example), a hypercomplex
// sqr, a moved and tilted slice, and one cut by a box (inside test).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 3, -8>
    look_at <0, 0.6, 0>
    angle 60
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, -1.2 pigment { color rgb 0.85 } }

julia_fractal {
    <-0.083, 0.0, -0.83, -0.025>
    quaternion sqr
    max_iteration 8
    precision 15
    translate <-2.6, 1.8, 0>
    pigment { color rgb <1, 0.6, 0.3> } finish { phong 0.6 }
}
julia_fractal {
    <-0.03, 0.5, -0.2, -0.5>
    max_iteration 8
    precision 15
    quaternion
    cube
    scale 1.3 rotate y*90 translate <0, 1.8, 0>
    pigment { color rgb <0.3, 0.7, 1> }
}
julia_fractal {
    <0.2, 0.1, 0.59, -0.2>
    max_iteration 7
    precision 15
    sqr
    hypercomplex
    scale 1.1 rotate <83, 0, -70> translate <2.6, 1.8, 0>
    pigment { color rgb <0.8, 0.65, 0.85> } finish { phong 0.7 }
}
julia_fractal {
    <-0.4, 0.4, 0.2, 0.1>
    quaternion sqr
    max_iteration 9
    precision 20
    slice <0, 0, 0.3, 1>, 0.2
    translate <-1.6, -0.1, -0.5>
    pigment { color rgb <0.4, 1, 0.4> }
}
intersection {
    julia_fractal { <-0.54, 0.57, 0.0, -0.37> max_iteration 8 precision 15 cube }
    box { <-2, -0.2, -2>, <2, 2, 2> }
    scale 1.4 translate <1.7, -0.3, 0>
    pigment { color rgb <1, 0.85, 0.2> }
}

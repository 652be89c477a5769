// Bicubic patches: the documentation's saddle (flatness 0, 4 x 4 steps) turned and scaled, a
// wavy sheet with different u and v steps, a dome quarter whose first row collapses to its
// apex (the teapot lid's case), and a patch seen from behind, over a checker floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 5, -10>
    look_at <0, 1, 0>
    angle 55
}

light_source { <5, 10, -6> color White }
light_source { <-8, 5, -3> color rgb 0.35 }

plane { y, -0.5 pigment { checker color rgb 0.9 color rgb 0.6 scale 2 } }

bicubic_patch {
    type 1 flatness 0 u_steps 4 v_steps 4
    <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>,
    <0, 1, 0>, <1, 1, 0>, <2, 1, 0>, <3, 1, 0>,
    <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
    <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2>
    pigment { color rgb <1, 0.4, 0.25> }
    finish { phong 0.6 }
    translate <-1.5, -1.5, 0>
    scale 0.8
    rotate <30, -40, 0>
    translate <-3, 2, 1>
}

bicubic_patch {
    type 0 u_steps 5 v_steps 3
    <0, 0, 0> <1, 1.5, 0> <2, -1, 0> <3, 0.5, 0>
    <0, 0.5, 1> <1, -1, 1> <2, 1.5, 1> <3, 0, 1>
    <0, 0, 2> <1, 1.5, 2> <2, -1, 2> <3, 0.5, 2>
    <0, 0.5, 3> <1, -1, 3> <2, 1.5, 3> <3, 0, 3>
    pigment { color rgb <0.3, 0.8, 0.4> }
    finish { specular 0.4 }
    scale <0.9, 0.6, 0.8>
    rotate y * 20
    translate <0.3, 0.4, 1.5>
}

#declare K = 0.5523;
bicubic_patch {
    type 1 flatness 0.0 u_steps 4 v_steps 4
    <0, 1, 0> <0, 1, 0> <0, 1, 0> <0, 1, 0>
    <K, 1, 0> <K, 1, K * K> <K * K, 1, K> <0, 1, K>
    <1, K, 0> <1, K, K> <K, K, 1> <0, K, 1>
    <1, 0, 0> <1, 0, K> <K, 0, 1> <0, 0, 1>
    pigment { color rgb <0.35, 0.5, 1> }
    finish { phong 0.8 phong_size 40 }
    scale 1.6
    rotate y * 200
    translate <3.2, -0.5, 0.5>
}

bicubic_patch {
    type 1 u_steps 3 v_steps 3
    <0, 0, 0> <1, 0, 0.6> <2, 0, 0.6> <3, 0, 0>
    <0, 1, 0.6> <1, 1, 1.5> <2, 1, 1.5> <3, 1, 0.6>
    <0, 2, 0.6> <1, 2, 1.5> <2, 2, 1.5> <3, 2, 0.6>
    <0, 3, 0> <1, 3, 0.6> <2, 3, 0.6> <3, 3, 0>
    pigment { color rgb <1, 0.85, 0.3> }
    translate <-1.5, 0, 0>
    scale 0.6
    rotate x * -10
    translate <0, 1.2, 4.5>
}

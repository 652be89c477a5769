// A focal-blur scene for `strahl tradeoff` (the blur_samples knob): the seed scene's floor and
// sphere seen through a lens focused on the sphere, with a near and a far ball out of focus.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <3, 3, -1>
    look_at <0, 1, 2>
    aperture 0.5
    blur_samples 32
    focal_point <0, 2, 4>
}

light_source { <0, 4, -3> color White }
light_source { <6, 4, -3> color rgb 0.6 }

plane { y, 0 pigment { checker color White color Black } }

sphere { <0, 2, 4>, 2 pigment { color Orange } finish { phong 1 } }
sphere { <2, 0.5, 0.5>, 0.5 pigment { color rgb <0.2, 0.5, 1> } }
sphere { <-3, 1, 9>, 1 pigment { color rgb <0.3, 0.9, 0.3> } }

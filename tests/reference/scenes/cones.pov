// Cylinders and cones, capped and open, and discs with and without a hole, lit from two sides
// so that caps, sides and the inside of open ends all show.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <1, 5, -8>
    look_at <0, 0.8, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

cylinder { <-3, 0, 0>, <-3, 2, 0>, 0.7 pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
cylinder { <-1.2, 0.2, -1.5>, <0.6, 1.2, -0.6>, 0.35 open pigment { color rgb <0.2, 0.6, 1> } }
cone { <0.8, 0, 1>, 0.9, <0.8, 2.2, 1>, 0 pigment { color rgb <0.3, 0.9, 0.3> } finish { specular 0.4 } }
cone { <2.6, 0.4, -1>, 0.2, <3.2, 1.6, -0.2>, 0.6 open pigment { color rgb <1, 0.8, 0.2> } }
cylinder { <0, 0, 0>, <0, 1, 0>, 0.5 scale <1, 0.6, 2> rotate y*30 translate <-1, 0, 2.5> pigment { color rgb <0.8, 0.4, 1> } }
disc { <-2.2, 1.8, -2>, <0.3, 1, -0.6>, 0.6 pigment { color rgb <1, 1, 0.4> } }
disc { <2, 2.6, 1.5>, <0, 0.4, -1>, 0.8, 0.35 pigment { color rgb <0.4, 1, 1> } }

// Superellipsoids: a sphere (<1, 1>), a rounded box, a rounded cylinder (along z, tipped),
// a pillow, a star-shaped one (exponents above 2: not convex), a diamond, under rotations
// and a non-uniform scale.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 5, -9>
    look_at <0, 0.8, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

superellipsoid { <1, 1> translate <-3, 1, 1> pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
superellipsoid { <0.2, 0.2> rotate y*30 translate <0, 1, 1.5> pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 } }
superellipsoid { <1, 0.15> rotate x*70 scale 0.8 translate <3, 0.9, 1> pigment { color rgb <0.3, 0.9, 0.3> } }
superellipsoid { <0.3, 1.5> scale <1, 0.4, 0.8> rotate y*-20 translate <-1.8, 0.4, -2> pigment { color rgb <1, 0.8, 0.2> } }
superellipsoid { <2.5, 2.5> scale 0.9 rotate <30, 20, 0> translate <1.6, 1, -1.8> pigment { color rgb <0.8, 0.4, 1> } }
superellipsoid { <2, 0.5> scale 0.6 rotate x*-90 translate <0, 0.6, -3.2> pigment { color rgb <1, 1, 0.6> } finish { phong 0.4 } }

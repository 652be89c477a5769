// Polynomial surfaces, bare (no bounded_by, no clipping): unbounded quadrics (a cylinder through
// the floor and out of the frame, an upward paraboloid, an hourglass hyperboloid), an ellipsoid
// written as a quadric (finite bounds), a cubic (a unit sphere times the tilted plane
// 0.3x + z - 5: a ball and a wall behind it), quartics (a torus around the x axis, fast solver;
// x^4 + y^4 + z^4 + 0.8xyz - 1 with sturm) and a poly of order 6 (x^6 + y^6 + z^6 + 0.4x^2y - 1).
// Coefficients in POV-Ray's order: x's power falling, then y's, then z's.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 4, -9>
    look_at <0, 1, 0>
    angle 60
}

light_source { <5, 10, -7> color White }
light_source { <-6, 5, -3> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

// x^2 + z^2 - 0.16: a vertical cylinder of radius 0.4.
quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.16 translate <3.6, 0, 1.5> pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
// x^2 + z^2 - y = 0: a bowl opening upwards, vertex on the floor.
quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 scale 0.6 translate <-3.2, 0, 2> pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 } }
// x^2 - y^2 + z^2 - 0.2 with an xz term: a tilted hourglass.
quadric { <1, -1, 1>, <0, 0.4, 0>, <0, 0, 0>, -0.2 scale 0.5 translate <0, 1.5, 5> pigment { color rgb <0.9, 0.8, 0.3> } }
// x^2 + 4y^2 + z^2 + xy - 1: an ellipsoid (bounded).
quadric { <1, 4, 1>, <1, 0, 0>, <0, 0, 0>, -1 scale 0.8 translate <1.5, 0.6, -2.5> pigment { color rgb <0.3, 0.9, 0.4> } finish { phong 0.4 } }
cubic { <0.3, 0, 1, -5, 0.3, 0, 0, 0.3, 0, -0.3, 0, 1, -5, 0, 0, 0, 1, -5, -1, 5> translate <-1.4, 1, 1> pigment { color rgb <0.9, 0.5, 0.9> } }
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, 1.755, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, -2.245, 0, 0, 0, 0, 1, 0, -2.245, 0, 0.77000625> rotate y*30 translate <-2.2, 0.9, -2> pigment { color rgb <1, 0.6, 0.2> } finish { phong 0.5 } }
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.8, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1> sturm scale 0.7 rotate <20, 30, 0> translate <0.5, 1, 0> pigment { color rgb <0.4, 0.7, 1> } }
poly { 6, <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0.4, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, -1> sturm scale 0.6 translate <2.4, 0.7, -0.5> pigment { color rgb <1, 1, 0.6> } }

// Prisms: a linear star with a hole (two sub-prisms, even-odd), quadratic and cubic rounded
// outlines, a bezier blob, a conic_sweep pyramid and an open, rotated linear prism.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 6, -9>
    look_at <0, 0.6, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

// Linear: a square with a square hole.
prism { linear_spline 0, 0.8, 10,
    <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>,
    <-0.4, -0.4>, <0.4, -0.4>, <0.4, 0.4>, <-0.4, 0.4>, <-0.4, -0.4>
    translate <-3, 0, 1.5> pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }

// Quadratic: the first point is a control point; the second closes the outline.
prism { quadratic_spline 0, 1.2, 6,
    <0.5, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>
    translate <0, 0, 2> pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 } }

// Cubic: first and last are control points.
prism { cubic_spline 0, 0.6, 7,
    <0, -1>, <1.2, 0>, <0, 1>, <-1.2, 0>, <0, -1>, <1.2, 0>, <0, 1>
    sturm translate <3, 0, 1.5> pigment { color rgb <0.3, 0.9, 0.3> } }

// Bezier: four points per segment, a two-lobed blob.
prism { bezier_spline 0, 0.5, 8,
    <-1, 0>, <-1, 1.4>, <1, 1.4>, <1, 0>,
    <1, 0>, <1, -0.8>, <-1, -1.6>, <-1, 0>
    translate <-1.8, 0, -2> pigment { color rgb <1, 0.8, 0.2> } }

// Conic sweep: a pyramid upside down, scaled so its apex is at the top.
prism { conic_sweep linear_spline 0, 1, 5,
    <1, 1>, <-1, 1>, <-1, -1>, <1, -1>, <1, 1>
    rotate x*180 translate y*1.4 scale 0.9 translate <1.2, 0, -1.6> pigment { color rgb <0.8, 0.4, 1> } }

// Open: no caps; seen from above it shows its inside.
prism { linear_spline -0.5, 0.5, 4, <0, 1>, <0.9, -0.6>, <-0.9, -0.6>, <0, 1>
    open rotate z*30 translate <3.4, 1, -1.5> pigment { color rgb <0.2, 0.8, 0.8> } }

// Isosurfaces: internal functions (f_sphere, f_torus, f_rounded_box, f_superellipsoid) and
// user functions with named parameters, calls and float functions; box and sphere containers,
// one cut by its box (the container's wall shows), one open, one with a threshold.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"
#include "functions.inc"

camera {
    location <0, 5, -10>
    look_at <0, 0.8, 0>
    angle 55
}

light_source { <5, 10, -6> color White }
light_source { <-8, 5, -3> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

#declare Wave = function(a, b) { 0.15 * sin(a * 4) * cos(b * 4) };
#declare Blobby = function { f_sphere(x, y, z, 1) + Wave(x, z) };

isosurface {
    function { Blobby(x, y, z) }
    contained_by { sphere { 0, 1.4 } }
    max_gradient 2
    translate <-3, 1.2, 1>
    pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 }
}
isosurface {
    function { f_torus(x, y, z, 0.9, 0.3) }
    contained_by { box { <-1.3, -0.4, -1.3>, <1.3, 0.4, 1.3> } }
    rotate x*-30 translate <0, 1.2, 2.5>
    pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 }
}
isosurface {
    function { f_rounded_box(x, y, z, 0.25, 0.8, 0.6, 0.8) }
    contained_by { box { -1, 1 } }
    rotate y*30 translate <3, 0.6, 1>
    pigment { color rgb <0.3, 0.9, 0.3> }
}
// A sphere of radius 1.2 cut by a smaller box: the box's faces close it.
isosurface {
    function { sqrt(x*x + y*y + z*z) - 1.2 }
    contained_by { box { -0.9, 0.9 } }
    rotate <20, 35, 0> translate <-1.2, 0.9, -2>
    pigment { color rgb <1, 0.8, 0.2> }
}
// A squarish tube flaring along y, open at the box: its inside shows through the ends.
isosurface {
    function { max(abs(x), abs(z)) + 0.3 * y * y }
    threshold 0.6
    contained_by { box { <-1, -1, -1>, <1, 1, 1> } }
    open
    max_gradient 1.8
    translate <1.6, 1, -2.2>
    pigment { color rgb <0.8, 0.4, 1> }
}

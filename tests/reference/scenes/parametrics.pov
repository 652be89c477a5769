// Parametric surfaces: the documentation's sphere (in a sphere container), a torus, a wavy
// open sheet cut by its box container, a twisted band (a shell seen from both sides).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 5, -10>
    look_at <0, 0.8, 0>
    angle 55
}

light_source { <5, 10, -6> color White }
light_source { <-8, 5, -3> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

parametric {
    function { sin(u) * cos(v) }
    function { sin(u) * sin(v) }
    function { cos(u) }
    <0, 0>, <pi, 2 * pi>
    contained_by { sphere { 0, 1.1 } }
    max_gradient 1.5
    accuracy 0.0001
    precompute 10 x, y, z
    translate <-3, 1.1, 1>
    pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 }
}
#declare R = 0.9;
#declare r = 0.3;
parametric {
    function { (R + r * cos(v)) * cos(u) }
    function { r * sin(v) }
    function { (R + r * cos(v)) * sin(u) }
    <0, 0>, <2 * pi, 2 * pi>
    contained_by { box { <-1.3, -0.4, -1.3>, <1.3, 0.4, 1.3> } }
    max_gradient 1.3
    rotate x*-30 translate <0, 1.2, 2.5>
    pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 }
}
// A wavy sheet over a larger rectangle than its box: cut at the box.
parametric {
    function { u }
    function { 0.25 * sin(3 * u) * cos(3 * v) }
    function { v }
    <-1.5, -1.5>, <1.5, 1.5>
    contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } }
    max_gradient 1
    rotate y*30 translate <3, 0.8, 1>
    pigment { color rgb <0.3, 0.9, 0.3> }
}
parametric {
    function { u * cos(v) }
    function { v * 0.25 }
    function { u * sin(v) }
    <-0.8, 0>, <0.8, 2 * pi>
    contained_by { box { <-1, 0, -1>, <1, 1.6, 1> } }
    max_gradient 1
    translate <-0.8, 0.1, -2>
    pigment { color rgb <1, 0.8, 0.2> }
}

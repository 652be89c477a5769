// Blobs: three spheres that merge, a negative component carving a dent, cylinder components
// with round ends, a component scaled into an ellipsoid, the old `component` syntax, and a
// blob cut by a box (inside test).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 4, -9>
    look_at <0, 1, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

blob {
    threshold 0.6
    sphere { <-0.6, 0, 0>, 1, 1 }
    sphere { <0.6, 0, 0>, 1, strength 1 }
    sphere { <0, 0.8, 0>, 1, 1 }
    sphere { <0, 0.3, -0.7>, 0.5, -1 }
    translate <-3, 1, 1>
    pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 }
}
blob {
    threshold 0.5
    cylinder { <-0.8, 0, 0>, <0.8, 0, 0>, 0.6, 1 }
    cylinder { <0, 0, 0>, <0, 1.6, 0>, 0.5, 1.5 }
    sphere { <0, 0, 0>, 1, 2 scale <1, 0.4, 1> translate y*1.6 }
    sturm
    rotate y*30 translate <0, 0.6, 1.5>
    pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 }
}
blob {
    threshold 0.4
    component 1, 0.9, <0, 0, 0>
    component 1, 0.9, <0.5, 0.5, 0>
    component 1, 0.9, <1, 0, 0>
    hierarchy off
    scale 1.2 rotate z*20 translate <2.2, 0.7, 0>
    pigment { color rgb <0.3, 0.9, 0.3> }
}
intersection {
    blob { threshold 0.3 sphere { <0, 0, 0>, 1.4, 1 } sphere { <0.8, 0.4, 0>, 1.0, 1 } }
    box { <-2, -2, -2>, <2, 0.2, 2> }
    translate <3.6, 1, 2.5>
    pigment { color rgb <1, 0.8, 0.2> }
}

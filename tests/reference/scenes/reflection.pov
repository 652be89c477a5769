// Mirrors: reflection recursing to max_trace_level between two facing mirrors.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
#include "colors.inc"

camera {
    location <0, 2.5, -7>
    look_at <0, 1, 0>
    angle 60
}

light_source { <-4, 8, -6> color White }
light_source { <5, 5, -2> color rgb <0.5, 0.5, 0.6> }
background { color rgb <0.2, 0.3, 0.5> }

plane {
    y, 0
    pigment { checker color rgb <0.9, 0.9, 0.8> color rgb <0.2, 0.3, 0.2> scale 1.5 }
    finish { reflection 0.2 }
}

sphere {
    <-1.3, 1.2, 0>, 1.2
    pigment { color rgb <0.9, 0.9, 0.95> }
    finish { ambient 0 diffuse 0.1 reflection 0.9 phong 0.8 phong_size 80 }
}

sphere {
    <1.4, 0.8, -0.6>, 0.8
    pigment { color Red }
    finish { reflection 0.3 specular 0.6 roughness 0.01 }
}

// Two facing mirrors: the ray bounces until max_trace_level.
box { <-4, 0, 3>, <4, 4, 3.2> pigment { color rgb 0.8 } finish { reflection 0.8 diffuse 0.2 } }
triangle {
    <-2, 0, 6>, <2, 0, 6>, <0, 3, 6>
    pigment { color Green }
}

// tests/reference/scenes/reflection.pov written in place around @P at scale @s(1), with a
// second, rotated mirror box and a polygon.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 6 }
#include "colors.inc"

camera {
    location @p(0, 2.5, -7)
    look_at @p(0, 1, 0)
    angle 60
}

light_source { @p(-4, 8, -6) color White }
light_source { @p(5, 5, -2) color rgb <0.5, 0.5, 0.6> }
background { color rgb <0.2, 0.3, 0.5> }

plane {
    y, @py(0)
    pigment { checker color rgb <0.9, 0.9, 0.8> color rgb <0.2, 0.3, 0.2> scale @s(1.5) translate @P }
    finish { reflection 0.2 }
}

sphere {
    @p(-1.3, 1.2, 0), @s(1.2)
    pigment { color rgb <0.9, 0.9, 0.95> }
    finish { ambient 0 diffuse 0.1 reflection 0.9 phong 0.8 phong_size 80 }
}

sphere {
    @p(1.4, 0.8, -0.6), @s(0.8)
    pigment { color Red }
    finish { reflection 0.3 specular 0.6 roughness 0.01 }
}

// Two facing mirrors: the ray bounces until max_trace_level.
box { @p(-4, 0, 3), @p(4, 4, 3.2) pigment { color rgb 0.8 } finish { reflection 0.8 diffuse 0.2 } }
box {
    @p(2.2, 0, -2.5), @p(3.4, 1.6, -2.3)
    pigment { color rgb <0.7, 0.8, 0.9> }
    finish { reflection 0.7 diffuse 0.3 }
    translate -@p(2.8, 0, -2.4)
    rotate y*-50
    translate @p(2.8, 0, -2.4)
}
triangle {
    @p(-2, 0, 6), @p(2, 0, 6), @p(0, 3, 6)
    pigment { color Green }
}
polygon {
    4, @p(-3.5, 0, -1), @p(-2.5, 0, -1.5), @p(-2.5, 1.5, -1.5), @p(-3.5, 1.5, -1)
    pigment { color rgb <0.9, 0.7, 0.2> }
    finish { reflection 0.3 }
}

// Wood and checker textures on boxes rotated in place (`translate -P rotate .. translate P`)
// around @P at scale @s(1).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location @p(3.5, 3, -4)
    look_at @p(0.3, 0.7, 0.6)
    angle 50
}

light_source { @p(-3, 8, -5) color White }
light_source { @p(5, 6, -2) color rgb 0.6 }
background { color rgb <0.3, 0.4, 0.6> }

plane {
    y, @py(0)
    pigment { checker color rgb 0.9 color rgb 0.25 scale @s(0.5) translate @P }
}

box {
    @p(-1, 0, -0.5), @p(1, 1.2, 1)
    pigment {
        wood
        turbulence 0.05
        color_map { [0 rgb <0.9, 0.6, 0.3>] [1 rgb <0.45, 0.25, 0.1>] }
        scale @s(0.15)
        rotate x*90
        translate @P
    }
    finish { specular 0.3 roughness 0.05 }
    translate -@P
    rotate y*30
    translate @P
}

box {
    @p(1.4, 0, 1.2), @p(2.2, 0.8, 2)
    pigment { checker color Red color White scale @s(0.2) translate @p(1.8, 0, 1.6) }
    translate -@p(1.8, 0, 1.6)
    rotate y*-40
    rotate x*8
    translate @p(1.8, 0, 1.6)
}

// A wood pigment whose axis passes through the box, untransformed except for the move.
box {
    @p(-2.4, 0, 1.5), @p(-1.4, 1.5, 2.5)
    pigment {
        wood
        color_map { [0 rgb <0.8, 0.5, 0.25>] [1 rgb <0.35, 0.2, 0.1>] }
        scale @s(0.1)
        translate @p(-1.9, 0, 2)
    }
    translate -@p(-1.9, 0, 2)
    rotate y*20
    translate @p(-1.9, 0, 2)
}

// tests/reference/scenes/refraction.pov written in place around @P at scale @s(1); the wall
// behind is turned and moved into place by a transform.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#include "colors.inc"

camera {
    location @p(0, 3, -6)
    look_at @p(0, 1, 0)
    angle 55
}

light_source { @p(-5, 10, -8) color White }
light_source { @p(6, 6, -4) color rgb 0.5 }
background { color rgb <0.1, 0.1, 0.2> }

plane {
    y, @py(0)
    pigment { checker color White color rgb <0.1, 0.3, 0.8> scale @s(0.7) translate @P }
}

// A wall behind, so refracted rays have something to show.
plane {
    z, 0
    pigment { checker color Yellow color rgb <0.6, 0.1, 0.1> scale @s(1) }
    rotate y*15
    translate @p(0, 0, 5)
}

sphere {
    @p(-1.2, 1.2, 0), @s(1.2)
    pigment { color rgbf <1, 1, 1, 0.95> }
    finish { ambient 0 diffuse 0 phong 0.9 phong_size 120 }
    interior { ior 1.5 }
}

// A thick slab seen at a grazing angle, rotated about its own axis in place.
box {
    @p(-0.5, 0.01, -0.5), @p(0.5, 2.2, 0.5)
    pigment { color rgbt <0.8, 1, 0.8, 0.9> }
    finish { ambient 0 diffuse 0.05 specular 0.5 }
    interior { ior 1.9 }
    translate -@P
    rotate y*35
    translate @p(1.6, 0, 0.3)
}

// Spheres under non-uniform scale (ellipsoids) around @P at scale @s(1): one written in place
// and scaled about its own centre, one a unit sphere scaled and then moved into place.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location @p(0, 2, -6)
    look_at @p(0, 1, 0)
    angle 50
}

light_source { @p(-4, 6, -5) color White }
light_source { @p(4, 3, -6) color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.4> }

plane {
    y, @py(0)
    pigment { checker color rgb 0.8 color rgb 0.3 scale @s(1) translate @P }
}

sphere {
    @p(-1.2, 1, 0), @s(1)
    pigment { color rgb <1, 0.5, 0.2> }
    finish { phong 0.8 }
    translate -@p(-1.2, 1, 0)
    scale <1.4, 0.6, 1>
    rotate z*25
    translate @p(-1.2, 1, 0)
}

sphere {
    <0, 0, 0>, 1
    pigment { color rgb <0.2, 0.5, 1> }
    normal { bumps 0.5 scale 0.15 }
    finish { phong 0.5 }
    scale @v(0.5, 1.2, 0.7)
    rotate y*30
    translate @p(1.5, 1.2, 0.5)
}

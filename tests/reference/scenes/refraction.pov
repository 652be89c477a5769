// Glass: refraction by Snell's law, and total internal reflection inside the sphere and the slab.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#include "colors.inc"

camera {
    location <0, 3, -6>
    look_at <0, 1, 0>
    angle 55
}

light_source { <-5, 10, -8> color White }
light_source { <6, 6, -4> color rgb 0.5 }
background { color rgb <0.1, 0.1, 0.2> }

plane {
    y, 0
    pigment { checker color White color rgb <0.1, 0.3, 0.8> scale 0.7 }
}

// A wall behind, so refracted rays have something to show.
plane {
    z, 5
    pigment { checker color Yellow color rgb <0.6, 0.1, 0.1> }
}

sphere {
    <-1.2, 1.2, 0>, 1.2
    pigment { color rgbf <1, 1, 1, 0.95> }
    finish { ambient 0 diffuse 0 phong 0.9 phong_size 120 }
    interior { ior 1.5 }
}

// A thick slab seen at a grazing angle: rays leaving it obliquely are totally reflected. It
// floats 0.01 above the floor: with its bottom face in the floor plane, which of the two a ray
// inside the glass meets first is decided by rounding, in POV-Ray as in strahl (f32 and f64
// disagreed on 2 400 pixels there, against 79 with the gap).
box {
    <-0.5, 0.01, -0.5>, <0.5, 2.2, 0.5>
    pigment { color rgbt <0.8, 1, 0.8, 0.9> }
    finish { ambient 0 diffuse 0.05 specular 0.5 }
    interior { ior 1.9 }
    rotate y*35
    translate <1.6, 0, 0.3>
}

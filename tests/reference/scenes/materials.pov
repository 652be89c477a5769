// material { }: declared materials with texture and interior, a material's own transforms
// (which move its texture, not the object), a material from a declared base with a layer over
// it, and a material given to a CSG object.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
#include "colors.inc"

camera {
    location <0, 3, -7>
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

plane {
    z, 5
    pigment { checker color Yellow color rgb <0.6, 0.1, 0.1> }
}

#declare M_Glass = material {
    texture {
        pigment { color rgbf <1, 1, 1, 0.95> }
        finish { ambient 0 diffuse 0 phong 0.9 phong_size 120 }
    }
    interior { ior 1.5 }
}

#declare M_Checks = material {
    texture {
        pigment { checker color Red color White }
        finish { ambient 0.2 diffuse 0.7 }
    }
    scale 0.25
}

// A declared material used as the base of another, with a layer over its texture.
#declare M_Striped = material {
    M_Checks
    texture { pigment { gradient x color_map { [0.5 rgbt 1] [0.5 rgb <0, 0.6, 0>] } scale 0.5 } }
}

sphere { <-2, 1, 0>, 1 material { M_Glass } }

// The material's scale moves the checks only, not the box.
box {
    <-0.6, 0, -0.6>, <0.6, 1.2, 0.6>
    material { M_Checks rotate y*30 }
    rotate y*20
    translate <0.2, 0, 0.5>
}

difference {
    sphere { <2.2, 1, 0>, 1 }
    cylinder { <2.2, 1, -2>, <2.2, 1, 2>, 0.45 }
    material { M_Striped }
}

sphere {
    <0.1, 0.4, -1.6>, 0.4
    material {
        texture { pigment { color rgbt <0.7, 0.9, 1, 0.8> } finish { ambient 0 diffuse 0.1 specular 0.6 } }
        interior { ior 1.33 }
    }
}

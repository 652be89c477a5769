// Layered textures: upper layers show the lower ones through their filter and transmit.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 0.8, 0> }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 6, -3> color rgb 0.5 }

plane { y, 0
    texture { pigment { rgb <0.6, 0.6, 0.5> } }
    texture { pigment { gradient x color_map { [0 rgbt <0.1, 0.1, 0.4, 0>] [0.3 rgbt <0.1, 0.1, 0.4, 0>] [0.3 rgbt 1] [1 rgbt 1] } } }
}
sphere { <-1.5, 1, 0>, 1
    texture { pigment { rgb <0.9, 0.5, 0.1> } finish { phong 0.6 } }
    texture { pigment { gradient y color_map { [0 rgbf <0.2, 0.2, 1, 0.6>] [0.5 rgbt <1, 1, 1, 1>] [1 rgbf <0.2, 0.2, 1, 0.6>] } scale 0.3 } }
}
box { <0.5, 0, -0.8>, <2.3, 1.8, 1>
    texture { pigment { checker rgb 1 rgb <0.2, 0.6, 0.2> scale 0.45 } }
    texture { pigment { onion color_map { [0 rgbt <0.8, 0, 0, 0>] [0.2 rgbt <0.8, 0, 0, 0>] [0.2 rgbt 1] [1 rgbt 1] } scale 0.5 } }
}

// The old `tiles` texture: a checker of two textures (layered ones too), with transforms after it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 4, -6>
    look_at <0, 0.5, 0>
    angle 50
}

light_source { <-5, 10, -8> color White }
background { color rgb <0.1, 0.1, 0.2> }

plane {
    y, 0
    texture {
        tiles {
            texture { pigment { color rgb <0.9, 0.85, 0.7> } finish { ambient 0.2 diffuse 0.7 } }
            tile2
            texture { pigment { color rgb <0.2, 0.1, 0.05> } finish { ambient 0.2 diffuse 0.7 } }
        }
        scale 0.8
        rotate y*15
    }
}

box {
    <-1, 0, -1>, <1, 1.5, 1>
    texture {
        tiles {
            texture { pigment { color Red } }
            tile2
            texture { pigment { gradient y color_map { [0 Blue] [1 Green] } } }
            texture { pigment { checker color rgbt 1 color rgbt <1, 1, 1, 0.5> scale 0.25 } }
        }
        scale 0.5
    }
    rotate y*30
    translate <0, 0, 1>
}

// The seed scene without noise patterns: every pixel should match POV-Ray closely.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <3, 3, -1>
    look_at <0, 1, 2>
}

light_source { <0, 4, -3> color White }
light_source { <0, 6, -4> color White }
light_source { <6, 4, -3> color White }

plane {
    <0, 1, 0>, 0
    pigment { checker color White color Black }
}

sphere {
    <0, 2, 4>, 2
    texture {
        pigment { color Orange }
        finish { phong 1 }
    }
}

box {
    <-1, 0, -0.5>, <1, 2, 1.5>
    pigment { color rgb <0.8, 0.55, 0.3> }
    finish { specular 0.4 roughness 0.02 }
    rotate y*(-20)
}

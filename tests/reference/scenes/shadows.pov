// Transparent shadows: filter tints the light, transmit passes it untinted.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 6, -7>
    look_at <0, 0.5, 0>
    angle 50
}

light_source { <2, 9, -3> color White }
light_source { <-6, 5, -1> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.9 } }

sphere {
    <-2, 1, 0>, 0.9
    pigment { color rgbf <1, 0.2, 0.2, 0.7> }
    finish { phong 0.5 }
}

sphere {
    <0, 1, 0.5>, 0.9
    pigment { color rgbt <0.2, 0.2, 1, 0.6> }
}

box {
    <1.2, 0.2, -0.6>, <2.8, 1.8, 0.6>
    pigment { color rgbft <0.2, 1, 0.2, 0.4, 0.3> }
    interior { ior 1 }
}

polygon {
    5, <-3, 0.01, -3>, <-1, 0.01, -3>, <-1, 0.01, -1.5>, <-3, 0.01, -1.5>, <-3, 0.01, -3>
    pigment { color rgb <0.9, 0.6, 0.1> }
}

triangle { <0, 2.5, -2>, <1, 2.5, -2.5>, <0.5, 3, -1.5> pigment { color Orange } }

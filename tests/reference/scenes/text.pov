// Text: timrom.ttf and cyrvetic.ttf strings (kerned pairs AV, To), one rotated and tilted, one
// with an offset between characters, on a floor they shadow.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 3, -7>
    look_at <0, 0.9, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

text { ttf "timrom.ttf" "AVAST Today" 0.3, 0
    scale 0.9 translate <-3, 1.6, 0> pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
text { ttf "cyrvetic.ttf" "Water, 3.7!" 0.5, <0.05, 0, 0>
    rotate y*-25 translate <-2.2, 0.3, -0.5> pigment { color rgb <0.2, 0.6, 1> } finish { specular 0.5 } }
text { ttf "timrom.ttf" "gyro" 0.2, <0, 0.1, 0>
    rotate <-20, 30, 10> scale 1.2 translate <1.4, 0.4, -1.5> pigment { color rgb <0.3, 0.9, 0.3> } }

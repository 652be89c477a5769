// assumed_gamma 2.2: POV-Ray 3.7 raises each colour to 2.2 before writing sRGB (darker).
#version 3.7;
global_settings { assumed_gamma 2.2 }

camera { location <0, 1, -4> look_at <0, 0.5, 0> sky <0.2, 1, 0> angle 60 }
light_source { <2, 4, -5> color rgb <1, 0.9, 0.8> }
plane { y, 0 pigment { checker color rgb <0.8, 0.5, 0.2> color rgb 0.1 } }
sphere { <0, 0.7, 0>, 0.7 pigment { color rgb <0.3, 0.6, 0.9> } finish { phong 0.5 specular 0.3 } }
box { <-2, 0, 1>, <-1, 1, 2> pigment { color rgb 0.5 } rotate x*15 }

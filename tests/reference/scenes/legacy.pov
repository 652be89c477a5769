// A legacy (3.6) scene without assumed_gamma: POV-Ray 3.7 writes linear values, no sRGB curve.
#version 3.6;

camera { location <0, 2, -5> look_at <0, 1, 0> }
light_source { <3, 6, -5> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.8 color rgb 0.2 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.2, 0.5, 0.9> } finish { phong 0.6 } }

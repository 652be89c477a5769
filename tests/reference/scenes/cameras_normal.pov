// Camera reference: a camera `normal` tilts every eye ray as a surface normal is tilted, the
// pattern read at the screen point (x, y, 0) and its slope taken along the world's axes.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 9, -6>
    look_at <0, 0, 1>
    angle 60
    normal { onion 0.25 sine_wave scale 0.4 translate <0.1, -0.05, 0> }
}

light_source { <4, 10, -6> color rgb 1 }
light_source { <-6, 6, 3> color rgb 0.4 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.15 scale 2 } }
sphere { <0, 1, 3>, 1 pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <-3, 0.8, 1>, 0.8 pigment { color rgb <0.2, 0.8, 0.3> } }
sphere { <3, 0.7, 0.5>, 0.7 pigment { color rgb <0.9, 0.8, 0.2> } }
box { <1.5, 0, 5>, <3.5, 2.5, 6> pigment { color rgb <0.3, 0.4, 1> } }
box { <-4, 0, -4>, <-2.5, 1.5, -2.5> pigment { color rgb <0.8, 0.3, 0.9> } }
sphere { <4, 1, -4>, 1 pigment { color rgb <0.2, 0.9, 0.9> } }
sphere { <0, 5, 2>, 0.8 pigment { color rgb <1, 0.6, 0.1> } }

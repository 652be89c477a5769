// The extremes test scene: the seed scene's shapes without noise patterns, so renders of it
// scaled and translated far from the origin can be compared pixel for pixel
// (tests/suite/extremes.rs transforms it as a SceneDesc, not through the parser).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 5 }

camera {
    location <3, 3, -1>
    look_at <0, 1, 2>
}

light_source { <0, 4, -3> color rgb 1 }
light_source { <6, 4, -3> color rgb <0.6, 0.6, 0.5> }

plane {
    <0, 1, 0>, 0
    pigment { checker color rgb 1 color rgb 0 scale 0.5 rotate y*10 }
}

sphere {
    <0, 2, 4>, 2
    pigment { color rgb <1, 0.5, 0> }
    finish { phong 1 }
}

sphere {
    <2.5, 0.5, 1.5>, 0.5
    pigment { color rgb <0.2, 0.4, 1> }
    finish { specular 0.6 roughness 0.02 reflection 0.3 }
}

box {
    <-1, 0, -0.5>, <1, 2, 1.5>
    pigment { color rgb <0.8, 0.55, 0.3> }
    finish { specular 0.4 roughness 0.02 }
    rotate y*(-20)
}

triangle {
    <-2, 0, 3>, <-0.5, 3, 5>, <-3, 2.5, 6>
    pigment { color rgb <0.3, 0.9, 0.3> }
}

sphere {
    <1.6, 0.7, 0.2>, 0.7
    pigment { color rgbf <0.9, 1, 0.9, 0.8> }
    finish { phong 0.5 }
    interior { ior 1.5 }
}

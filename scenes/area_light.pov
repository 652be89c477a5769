// Soft shadows for `strahl tradeoff`: an 8×8 jittered area light (64 shadow rays per lit
// point) and a fill light, over spheres and a box on a floor. Its cost knob is
// `--max-area-samples` (the presets cap it: fast 4, balanced 16).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 6, -9>
    look_at <0, 0.8, 0.5>
    angle 50
}

light_source {
    <-3, 8, -4> color rgb 0.9
    area_light <4, 0, 0>, <0, 0, 4>, 8, 8
    jitter
}
light_source { <6, 5, -6> color rgb 0.25 shadowless }

plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.6 scale 2 } }

sphere { <-1.5, 1, 0.5>, 1 pigment { color rgb <1, 0.5, 0.4> } finish { phong 0.5 } }
sphere { <1.5, 0.7, -0.5>, 0.7 pigment { color rgb <0.5, 0.7, 1> } }
box { <0.5, 0, 1.5>, <2.5, 2.2, 2.5> rotate y * 20 pigment { color rgb <0.9, 0.9, 0.6> } }

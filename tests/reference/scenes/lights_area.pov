// Area lights as soft shadows, without jitter so that the comparison is deterministic: a 5×5
// rectangular light and a 4×4 circular light, both adaptive 1, over spheres and a box.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 7, -9>
    look_at <0, 0.5, 0.5>
    angle 50
}

light_source {
    <-4, 8, -3> color rgb 0.8
    area_light <3, 0, 0>, <0, 0, 3>, 5, 5
    adaptive 1
}

light_source {
    <5, 6, 2> color rgb <0.5, 0.45, 0.4>
    area_light <2, 0, 0>, <0, 2, 0>, 4, 4
    circular
}

plane { y, 0 pigment { color rgb 0.85 } }

sphere { <-1.5, 1, 0.5>, 1 pigment { color rgb <1, 0.5, 0.4> } }
sphere { <1.5, 0.7, -0.5>, 0.7 pigment { color rgb <0.5, 0.7, 1> } }
box { <0.5, 0, 1.5>, <2.5, 2.2, 2.5> pigment { color rgb <0.9, 0.9, 0.6> } }

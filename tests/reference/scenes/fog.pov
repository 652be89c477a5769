// Fog: a constant fog and a ground fog layer over a checkered floor, seen to the horizon,
// with a mirror sphere whose reflection is fogged along its own ray.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 2, -6>
    look_at <0, 1, 4>
    angle 60
}

light_source { <5, 10, -6> color rgb 1 }
background { color rgb <0.2, 0.3, 0.6> }

fog { distance 40 color rgb <0.7, 0.7, 0.75> }
fog { fog_type 2 distance 6 color rgbt <0.9, 0.8, 0.7, 0.2> fog_offset 0.3 fog_alt 0.6 }

plane { y, 0 pigment { checker color rgb 1 color rgb <0.2, 0.3, 0.2> } }
sphere { <-2, 1, 3>, 1 pigment { color rgb <1, 0.3, 0.2> } }
sphere { <1.5, 1.2, 8>, 1.2 pigment { color rgb 0.2 } finish { reflection 0.7 } }
box { <3, 0, 14>, <5, 3, 16> pigment { color rgb <0.3, 0.5, 1> } }

// sky_sphere: a checker pigment on the sky (scaled, rotated) over a solid layer, seen
// directly and in a mirror sphere; solid and checker are the patterns strahl has here.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 1.5, -5>
    look_at <0, 1.5, 0>
    angle 70
}

light_source { <4, 8, -6> color rgb 1 }

sky_sphere {
    pigment { color rgb <0.3, 0.5, 0.9> }
    pigment { checker color rgbt <1, 1, 1, 1> color rgb <0.9, 0.6, 0.3> scale 0.25 }
    rotate y * 20
    emission rgb 0.9
}

plane { y, 0 pigment { color rgb <0.4, 0.6, 0.3> } }
sphere { <0, 1.2, 1>, 1.2 pigment { color rgb 0 } finish { reflection 0.9 ambient 0 diffuse 0 } }

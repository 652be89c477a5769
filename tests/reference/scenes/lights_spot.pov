// Light kinds: a spotlight (radius, falloff, tightness), a cylinder light, a parallel light
// and a fading point light, each with its shadow on a floor; a spotlight with a negative falloff.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera {
    location <0, 9, -10>
    look_at <0, 0, 0.5>
    angle 55
}

// Spotlight from above on the left, hot spot 12°, edge at 22°, a little tightness.
light_source {
    <-3, 7, -1> color rgb <1, 0.9, 0.7>
    spotlight
    point_at <-3, 0, 1>
    radius 12 falloff 22 tightness 5
}

// A dim spotlight with a negative falloff from the mesh_camera samples: POV-Ray opens it as
// `falloff 90` (by the angle's cosine), lighting the whole half-space below.
light_source {
    <0, 6, -6> color rgb 0.25
    spotlight
    point_at <0, 0, 0>
    radius 40 falloff -90 tightness 1
}

// Cylinder light straight down on the right: 1 unit hot core, falls off to 1.6.
light_source {
    <3.5, 10, 1.5> color rgb <0.6, 0.8, 1>
    cylinder
    point_at <3.5, 0, 1.5>
    radius 1 falloff 1.6
}

// Parallel light, low and from the front right: long parallel shadows.
light_source {
    <20, 12, -20> color rgb 0.35
    parallel
    point_at <0, 0, 0>
}

// A fading point light near the back: bright close, dim far.
light_source {
    <0, 1.5, 5> color rgb <1, 0.5, 0.3>
    fade_distance 2.5 fade_power 2
}

plane { y, 0 pigment { color rgb 0.8 } }

sphere { <-3, 1, 1>, 1 pigment { color rgb <1, 1, 1> } finish { phong 0.4 } }
box { <2.8, 0, 0.8>, <4.2, 1.5, 2.2> pigment { color rgb <0.9, 0.9, 0.5> } }
cylinder { <0, 0, 0>, <0, 2, 0>, 0.5 pigment { color rgb <0.5, 1, 0.5> } }
sphere { <1.5, 0.6, 4>, 0.6 pigment { color rgb 1 } }

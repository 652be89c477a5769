// Warps move the pigments a pattern is made of too: an `average` of two declared gradients
// pulled into a black hole where it is used, a checker of pigments turned by a spherical warp
// written after a scale, and a pigment_map whose entries are repeated.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }

#declare F = finish { ambient 1 diffuse 0 }
#declare P = pigment {
    average
    pigment_map {
        [1 gradient x color_map { [0 rgb 0] [1 rgb <1, 0, 0>] } scale 0.3]
        [1 gradient y color_map { [0 rgb 0] [1 rgb <0, 1, 0>] } scale 0.3]
    }
}
box { <-1.9, -1.4, 0>, <1.9, 1.4, 0.1> pigment { P warp { black_hole <0, 0, 0>, 1.2 } } finish { F } translate <-2, 1.5, 0> }
box { <-1.9, -1.4, 0>, <1.9, 1.4, 0.1>
    pigment {
        checker
        pigment { gradient x color_map { [0 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] } scale 0.2 }
        pigment { gradient y color_map { [0 rgb <0.1, 0.2, 0.8>] [1 rgb 1] } scale 0.3 }
        scale 0.5
        warp { spherical orientation y }
        translate z * 0.4
    }
    finish { F }
    translate <2, 1.5, 0>
}
box { <-1.9, -1.4, 0>, <1.9, 1.4, 0.1>
    pigment {
        gradient x
        pigment_map {
            [0 gradient y color_map { [0 rgb <1, 0.9, 0.2>] [1 rgb <0.1, 0.2, 0.8>] } scale 0.25]
            [1 gradient <1, 1, 0> color_map { [0 rgb <0.8, 0.1, 0.1>] [1 rgb 1] } scale 0.4]
        }
        scale 1.5
        warp { repeat x * 0.6 offset <0, 0.2, 0> flip x }
    }
    finish { F }
    translate <-2, -1.5, 0>
}

// Light groups: a red light that lights only its group's sphere (global_lights off), a blue
// light whose group also takes the global light (global_lights on), a nested group that
// inherits its parent's light, a group transformed as a whole, and a difference of two
// groups lit differently (POV-Ray 3.4.4.2's example). The global light lights the rest.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 4, -10>
    look_at <0, 1, 0>
    angle 55
}

light_source { <3, 10, -8> color rgb 0.9 }

plane { y, 0 pigment { color rgb 0.8 } }

light_group {
    light_source { <-8, 6, -4> color rgb <1, 0.2, 0.1> }
    sphere { <-3.5, 1, 0>, 1 pigment { color White } finish { phong 0.5 } }
    global_lights off
}

light_group {
    light_source { <8, 2, -6> color rgb <0.1, 0.3, 1> }
    sphere { <-1.2, 1, 1>, 1 pigment { color White } }
    box { <-0.6, 0, -2.6>, <0.6, 0.8, -1.6> pigment { color rgb <1, 1, 0.6> } }
    global_lights on
}

#declare Inner = light_group {
    light_source { <0, 8, 2> color rgb <0.2, 1, 0.2> }
    sphere { <0, 0, 0>, 0.6 pigment { color White } }
};
light_group {
    light_source { <4, 3, -8> color rgb <1, 0.8, 0.3> }
    object { Inner }
    cylinder { <0, 0, 0>, <0, 0.8, 0>, 0.5 pigment { color White } translate <1, 0, 0> }
    translate <1.4, 0.6, -1>
}

difference {
    light_group {
        sphere { 0, 1 pigment { color White } }
        light_source { <-100, 0, -100> color rgb <1, 0, 0> }
        global_lights off
    }
    light_group {
        sphere { <0, 1, 0>, 1 pigment { color White } }
        light_source { <100, 100, 0> color rgb <0, 0, 1> }
        global_lights off
    }
    rotate <-45, 0, 0>
    translate <3.6, 1.2, 1>
}

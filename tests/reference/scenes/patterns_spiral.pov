// spiral1 with its default triangle wave (POV-Ray 3.4.7.1.25), with a colour map, an explicit
// ramp_wave, a sine_wave and a frequency, seen head-on with ambient light only.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 0, -10> look_at 0 right 8*x up 6*y }
#declare Map = color_map { [0 rgb <0.1, 0.1, 0.4>] [0.5 rgb <1, 0.8, 0.3>] [1 rgb <0.9, 0.2, 0.1>] }
#declare F = finish { ambient 1 diffuse 0 }
plane { z, 0 pigment { spiral1 5 color_map { Map } scale 0.5 translate <-2, 1.5, 0> } finish { F } clipped_by { box { <-4, 0, -1>, <0, 3, 1> } } }
plane { z, 0 pigment { spiral1 3 ramp_wave color_map { Map } scale 0.5 translate <2, 1.5, 0> } finish { F } clipped_by { box { <0, 0, -1>, <4, 3, 1> } } }
plane { z, 0 pigment { spiral1 4 frequency 2 color_map { Map } scale 0.6 translate <-2, -1.5, 0> } finish { F } clipped_by { box { <-4, -3, -1>, <0, 0, 1> } } }
plane { z, 0 pigment { spiral1 2 sine_wave color_map { Map } scale 0.5 rotate 30*z translate <2, -1.5, 0> } finish { F } clipped_by { box { <0, -3, -1>, <4, 0, 1> } } }

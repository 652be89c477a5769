// The slope pattern: a texture_map and a colour map picked by the angle between the surface's
// normal and a direction (world axes), stretched by Lo/Hi, averaged with an altitude gradient
// (pattern space), aimed at a point, nested in a map whose transform comes before the map, and
// POV-Ray 3.5's bare `slope V`. Ambient only, so the pattern value is what shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { orthographic location <0, 0, -10> look_at 0 right x * 8 up y * 6 }
background { rgb <0.2, 0.3, 0.25> }

#declare F = finish { ambient 1 diffuse 0 }
#declare T0 = texture { pigment { rgb <0.1, 0.2, 0.6> } finish { F } }
#declare T1 = texture { pigment { rgb <1, 0.9, 0.5> } finish { F } }
#declare TS = texture { slope { y * 3, 0, 0.5 altitude y, 0.005, 0.4 } texture_map { [0 T0] [1 T1] } }

sphere { <-2.7, 1.5, 0>, 1.2 texture { slope { y } texture_map { [0 T0] [0.5 T1] [1 T0] } } }
sphere { <0, 1.5, 0>, 1.2 pigment { slope { y, 0.25, 0.75 } color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.2>] } } finish { F } }
sphere { 0, 1.2 texture { slope { y * 3 altitude x, -1, 1 } texture_map { [0 T0] [1 T1] } translate x * 0.5 } translate <2.7, 1.5, 0> }
sphere { <-2.7, -1.5, 0>, 1.2 texture { slope { point_at <0, 10, -10> } texture_map { [0 T0] [1 T1] } } }
sphere { 0, 1 texture { gradient y scale 3 texture_map { [0 TS] [0.5 TS] [0.5 T1] [1 T1] } } scale 1.2 translate <0, -1.5, 0> }
sphere { 0, 1 texture { slope -x texture_map { [0 T0] [0.5 T1] [1 T0] } } scale <1.2, 0.8, 1.2> rotate z * 30 translate <2.7, -1.5, 0> }

// A rainbow: 120° arc with 30° soft ends, a translucent colour map, small jitter, over a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -5> look_at <0, 1, 0> angle 90 }
light_source { <0, 10, -10> color rgb 1 }
background { color rgb <0.3, 0.4, 0.7> }
rainbow { angle 42.5 width 5 distance 1.0e7 direction <-0.2, -0.2, 1> jitter 0.01
  color_map { [0 color rgbt <1,0,0,0.5>] [0.5 color rgbt <0,1,0,0.5>] [1 color rgbt <0,0,1,0.5>] } arc_angle 120 falloff_angle 30 }
plane { y, 0 pigment { color rgb 0.5 } }

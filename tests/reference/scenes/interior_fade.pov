// Interior fading (fade_distance, fade_power, fade_color): clear glass of three thicknesses
// and powers, an exponential one (power 1000), a declared interior modified, and the coloured
// shadows they cast (shadow rays fade through them too).
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }

camera { location <0, 4, -9> look_at <0, 0.8, 0> angle 55 }
light_source { <3, 10, -6> color rgb 1 }
background { rgb <0.3, 0.35, 0.4> }

plane { y, 0 pigment { checker rgb 0.9 rgb 0.5 scale 1.5 } finish { ambient 0.2 diffuse 0.8 } }

#declare Glass = texture { pigment { rgbf <1, 1, 1, 1> } finish { ambient 0 diffuse 0 specular 0.6 roughness 0.01 } }
#declare Blue = interior { ior 1.3 fade_distance 0.8 fade_power 2 fade_color <0.2, 0.4, 0.9> }

sphere { <-2.6, 1, 0>, 1 texture { Glass } interior { Blue } }
sphere { <0, 1, 0>, 1 texture { Glass } interior { ior 1.0 fade_distance 1.5 fade_power 1 fade_color <0.9, 0.3, 0.1> } }
sphere { <2.6, 1, 0>, 1 texture { Glass } interior { Blue fade_power 1001 fade_distance 1 } }
box { <-1.2, 0, -2.6>, <1.2, 0.5, -2.2> texture { Glass } interior { ior 1.5 fade_distance 0.3 fade_power 2 fade_color <0.1, 0.8, 0.3> } }
cylinder { <-3.5, 0, -2.5>, <-3.5, 2.2, -2.5>, 0.4 texture { Glass } interior { Blue } }

// Patterns of whole textures (textures that differ in finish or normal, not only pigment):
// the `object` pattern (declared and written out), a list pattern of textures, a
// `texture_map` blending a matte and a mirror texture, and a `material_map` whose palette
// index picks the texture; plus patterns' default colour maps (marble, radial; bozo's and
// agate's are noise, measured in lower::textures).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4.5, -7> look_at <0, 0.8, 0.8> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }
sky_sphere { pigment { gradient y color_map { [0 rgb <0.9, 0.9, 1>] [1 rgb <0.3, 0.4, 0.8>] } } }
#declare Star = union { sphere { <0, 0, 0>, 0.6 } box { <-0.2, -1, -0.2>, <0.2, 1, 0.2> } }
plane { y, 0 pigment { object { Star color rgb <0.9, 0.9, 0.8> color rgb <0.8, 0.1, 0.1> } scale 1.2 translate <-1.2, 0, -2.4> } }
// Object pattern of pigments, the object written out.
box { <-0.8, 0, -0.8>, <0.8, 1.6, 0.8>
  pigment { object { sphere { <0, 0.8, -0.8>, 0.7 } pigment { checker rgb 1 rgb 0 scale 0.25 }, pigment { rgb <0.2, 0.4, 0.9> } } }
  rotate y*30 translate <-2.6, 0, 0.8> }
// Object pattern of textures: a mirror band across a matte green ball.
sphere { <0, 1, 0>, 1
  texture { object { box { <-0.3, -2, -2>, <0.3, 2, 2> }
    texture { pigment { rgb <0.3, 0.8, 0.3> } }
    texture { pigment { rgb 1 } finish { reflection 0.6 } } } translate <0, 1, 0> } }
// A texture_map from matte red to a bumpy mirror, blended in between.
sphere { <2.6, 1, 0.8>, 1
  texture { gradient x
    texture_map {
      [0.3 pigment { rgb <0.8, 0.2, 0.1> } finish { phong 0.8 }]
      [0.7 pigment { rgb 0.9 } normal { gradient y 0.6 scale 0.2 } finish { reflection 0.7 diffuse 0.2 }]
    }
    scale 2 translate <1.6, 0, 0> } }
// material_map: 4 palette indices, 3 textures (index 3 gets the last).
box { <-1, -1, -0.1>, <1, 1, 0.1> translate <-1.2, 1.0, 3.2>
  texture { material_map { png "../images/pal8.png"
      texture { pigment { rgb <0.9, 0.8, 0.2> } finish { ambient 0.3 } }
      texture { pigment { rgb <0.1, 0.1, 0.1> } finish { reflection 0.8 } }
      texture { pigment { rgb <0.2, 0.5, 0.9> } normal { gradient x 0.8 scale 0.1 } }
      texture { pigment { rgb <0.9, 0.3, 0.6> } finish { specular 0.8 roughness 0.02 } }
    } translate <-0.5, -0.5, 0> scale 2 translate <-1.2, 1.0, 3.1> } }
// Default colour maps.
sphere { <1.2, 0.5, 3.0>, 0.5 pigment { marble scale 0.3 } }
sphere { <1.4, 0.4, -1.9>, 0.4 pigment { radial frequency 3 } }

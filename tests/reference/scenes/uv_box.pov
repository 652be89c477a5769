// uv_mapping on boxes: POV-Ray 3.7 unfolds the six faces into a cross four faces wide and three
// high (-x, +z, +x, -z round the middle row, +y above +z, -y below it). Cubes, a long box and
// a slab, with an image_map or a checker of stripes coloured by the cross's column; one cube
// seen from below; `uv_mapping` on the object, the texture and the pigment; rotated and
// scaled so that the object's transforms must not move the uv-mapped pigment.
// Lit flatly (ambient 1) so the pattern is what is compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -9> look_at <0, 0, 0> angle 50 }
background { color rgb <0.3, 0.5, 0.8> }
#declare Flat = finish { ambient 1 diffuse 0 };
#declare Img = "../images/test16.png"
// A colour for each column of the cross (a quarter of u), checkered with white.
#declare Cells = pigment {
  gradient x color_map { [0 rgb <1, 0.2, 0.1>] [0.25 rgb <1, 0.2, 0.1>] [0.25 rgb <0.2, 0.8, 0.2>]
    [0.5 rgb <0.2, 0.8, 0.2>] [0.5 rgb <0.2, 0.3, 1>] [0.75 rgb <0.2, 0.3, 1>] [0.75 rgb <1, 0.9, 0.2>] [1 rgb <1, 0.9, 0.2>] }
}
#declare Check = pigment { checker pigment { Cells } pigment { rgb 1 } scale <1 / 16, 1 / 12, 1> }

box { -1, 1 uv_mapping pigment { image_map { png Img } } finish { Flat } rotate <0, 35, 0> translate <-2.6, 1.2, 0> }
box { <-1, -0.5, -0.5>, <1, 0.5, 0.5>
  texture { uv_mapping pigment { Check } finish { Flat } } rotate <-25, -30, 0> scale 1.2 translate <0.3, 1.2, 0> }
box { -1, 1 texture { pigment { uv_mapping checker pigment { Cells } pigment { rgb 1 } scale <1 / 8, 1 / 6, 1> } finish { Flat } } rotate <0, -40, 0> translate <2.7, 1.0, 0> }
// Seen from below: the -y face, and the long faces of a flat slab.
box { -1, 1 uv_mapping pigment { Check } finish { Flat } rotate <150, 20, 0> translate <-1.5, -1.6, -1> }
box { <-1.5, -0.2, -1>, <1.5, 0.2, 1> uv_mapping pigment { image_map { png Img } } finish { Flat }
  rotate <-50, 15, 10> translate <2, -1.4, -1> }

// interior_texture: the texture a ray sees where it meets a surface from inside (against its
// outward normal): an open cylinder, a disc seen from its back, and a union whose
// interior_texture goes to the children that have none, moved by a transform after it. No
// noise: compared whole. (Not here, see docs/language.md, interior_texture: triangles, whose inner side POV-Ray takes
// the other way round; a sphere cut open by clipped_by, whose shell shadows its own inside
// differently; a mirrored interior behind a clear outside.)
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 8 }

camera { location <0, 4, -10> look_at <0, 0.6, 0> angle 52 }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <5, 3, -9> color rgb 0.4 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, -1 pigment { checker rgb 0.9 rgb 0.3 } }

cylinder { <0, -1, 0>, <0, 1.5, 0>, 0.9 open
  pigment { rgb <0.9, 0.2, 0.2> }
  interior_texture { pigment { checker rgb <0.1, 0.8, 0.2> rgb 1 scale 0.3 } }
  rotate x * -35 translate <0.2, 0.3, 1>
}
disc { <3, 0.8, 0>, <-0.5, 0.3, 1>, 1
  pigment { rgb <1, 1, 0> } interior_texture { pigment { rgb <0.6, 0, 0.8> } }
}
union {
  cylinder { <0, 0, 0>, <0, 1, 0>, 0.5 open }
  cylinder { <0, 0, 0>, <0, 1, 0>, 0.3 open pigment { rgb <1, 1, 0.6> } interior_texture { pigment { rgb <0, 0, 1> } } }
  pigment { rgb <1, 1, 1> }
  interior_texture { pigment { gradient y color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 1, 0>] } } }
  scale <1, 1.4, 1> translate <2.4, -1, 2.4>
}

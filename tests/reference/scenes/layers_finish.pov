// Layered textures whose layers differ in finish: each layer is shaded with its own finish
// (POV-Ray 3.7), not the bottom one's. A red diffuse layer under partly transparent layers
// with specular, phong, reflection and ambient; a filtered layer; three layers; a glassy
// bottom layer; layers on a plane. strahl's tests/suite/reference.rs compares it with POV-Ray's render.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -11> look_at <0, 0.3, 0> angle 50 }
light_source { <-20, 30, -25> rgb 1 }
light_source { <25, 10, -20> rgb 0.5 }
background { rgb <0.2, 0.3, 0.5> }
#declare Red = texture { pigment { rgb <1, 0.1, 0.1> } finish { ambient 0.05 diffuse 0.8 } }
plane { y, -1.2
  texture { pigment { checker rgb 0.9 rgb 0.3 } finish { ambient 0.1 diffuse 0.7 } }
  texture { pigment { rgbt <0.2, 0.3, 1, 0.7> } finish { ambient 0 diffuse 0.3 reflection 0.25 } }
}
// Back row.
sphere { <-3.4, 0.3, 1.5>, 1.1
  texture { Red }
  texture { pigment { rgbt <0, 0, 1, 0.6> } finish { ambient 0 diffuse 0.6 specular 0.8 roughness 0.01 } }
}
sphere { <0, 0.3, 1.5>, 1.1
  texture { Red }
  texture { pigment { rgbt <1, 1, 1, 0.8> } finish { ambient 0 diffuse 0.2 reflection 0.4 } }
}
sphere { <3.4, 0.3, 1.5>, 1.1
  texture { Red }
  texture { pigment { rgbf <0.2, 1, 0.2, 0.7> } finish { ambient 0.4 diffuse 0.3 phong 0.7 phong_size 40 } }
}
// Front row.
sphere { <-2.2, -0.4, -1.5>, 0.8
  texture { Red }
  texture { pigment { gradient y color_map { [0 rgbt <1, 1, 0, 0.2>] [1 rgbt <1, 1, 0, 1>] } scale 0.5 }
            finish { ambient 0 diffuse 0.9 phong 0.5 } }
  texture { pigment { rgbt <0, 0.5, 1, 0.75> } finish { ambient 0 diffuse 0.4 reflection 0.15 } }
}
sphere { <0, -0.4, -1.5>, 0.8
  texture { pigment { rgbt <1, 0.2, 0.2, 0.6> } finish { ambient 0 diffuse 0.7 } }
  texture { pigment { rgbt <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0 phong 0.9 phong_size 80 reflection 0.1 } }
}
box { <1.4, -1.2, -2.3>, <3, 0.4, -0.7>
  texture { pigment { rgb <0.9, 0.8, 0.2> } finish { ambient 0.1 diffuse 0.6 phong 0.4 } }
  texture { pigment { brick rgbt <1, 1, 1, 1> rgbt <0.6, 0.2, 0.1, 0.3> brick_size 0.4 mortar 0.05 }
            finish { ambient 0.2 diffuse 0.5 } }
}

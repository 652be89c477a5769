// Layered textures whose layers carry different normals: POV-Ray 3.7 lights each layer with
// its own normal (the surface's where a layer has none) and refracts by the top layer's. A
// bumped red layer under a flat blue one, the reverse with a highlight, two normals at once
// with a reflection, a glass ball whose bottom layer alone is bumped, three layers with the
// middle one bumped, and a floor whose top layer alone is. Exact patterns only (onion,
// radial, gradient), so the whole image compares. tests/suite/reference.rs compares it with
// POV-Ray's render.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -11> look_at <0, 0.3, 0> angle 50 }
light_source { <-20, 30, -25> rgb 1 }
light_source { <25, 10, -20> rgb 0.5 }
background { rgb <0.2, 0.3, 0.5> }
#declare Red = texture { pigment { rgb <1, 0.1, 0.1> } finish { ambient 0.05 diffuse 0.8 } }
#declare Bumped_Red = texture { Red normal { gradient <1, 1, 0> 0.8 triangle_wave scale 0.3 } }
plane { y, -1.2
  texture { pigment { checker rgb 0.9 rgb 0.3 } finish { ambient 0.1 diffuse 0.7 } }
  texture { pigment { rgbt <0.2, 0.3, 1, 0.7> } normal { gradient x 1 triangle_wave scale 0.8 }
            finish { ambient 0.1 diffuse 0.7 } }
}
// Back row.
sphere { <-3.4, 0.3, 1.5>, 1.1
  texture { Bumped_Red }
  texture { pigment { rgbt <0, 0, 1, 0.6> } finish { ambient 0.05 diffuse 0.8 } }
}
sphere { <0, 0.3, 1.5>, 1.1
  texture { Red }
  texture { pigment { rgbt <1, 1, 0.2, 0.5> } normal { onion 0.7 scale 0.3 }
            finish { ambient 0.05 diffuse 0.8 phong 0.6 phong_size 30 } }
}
sphere { <3.4, 0.3, 1.5>, 1.1
  texture { Bumped_Red }
  texture { pigment { rgbt <1, 1, 1, 0.8> } normal { gradient y 0.5 triangle_wave scale 0.4 }
            finish { ambient 0 diffuse 0.2 reflection 0.3 } }
}
// Front row.
sphere { <-2.2, -0.4, -1.5>, 0.8
  texture { pigment { rgbt <0.9, 1, 0.9, 0.9> } normal { onion 0.6 scale 0.2 } finish { ambient 0 diffuse 0.1 } }
  texture { pigment { rgbt <1, 1, 1, 0.95> } finish { ambient 0 diffuse 0.1 phong 0.8 } }
  interior { ior 1.5 }
}
sphere { <0, -0.4, -1.5>, 0.8
  texture { Red }
  texture { pigment { rgbt <0.2, 1, 0.2, 0.6> } normal { radial 0.7 frequency 8 rotate 90*x }
            finish { ambient 0.05 diffuse 0.8 } }
  texture { pigment { rgbt <1, 1, 1, 0.7> } finish { ambient 0 diffuse 0.3 specular 0.6 roughness 0.02 } }
}
box { <1.4, -1.2, -2.3>, <3, 0.4, -0.7>
  texture { pigment { rgb <0.9, 0.8, 0.2> } normal { gradient y 0.5 scale 0.25 } finish { ambient 0.1 diffuse 0.6 } }
  texture { pigment { rgbf <0.6, 0.2, 1, 0.6> } finish { ambient 0.1 diffuse 0.6 } }
}

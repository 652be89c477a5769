// slope_map in normals: several maps (two-entry, three-entry, with a sharp edge, a step in
// height, a map starting above 0), wave types and frequency, on planes and spheres, lit from
// the side so the tilt shows. strahl's tests/suite/reference.rs compares it with POV-Ray 3.7's render.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -12> look_at <0, 0, 0> angle 48 }
light_source { <-30, 20, -30> rgb 1 }
light_source { <40, -10, -20> rgb 0.4 }
#declare Tri = slope_map { [0 <0, 1>] [0.5 <1, 1>] [0.5 <1, -1>] [1 <0, -1>] }
#declare Fin = finish { ambient 0.1 diffuse 0.8 phong 0.5 phong_size 30 }
// Background plane: a sine wave the hard way on gradient x.
plane { -z, -2
  pigment { rgb <0.9, 0.85, 0.7> }
  finish { Fin }
  normal { gradient x 1
    slope_map { [0 <0.5, 1>] [0.25 <1, 0>] [0.5 <0.5, -1>] [0.75 <0, 0>] [1 <0.5, 1>] }
    scale 0.7 }
}
// Top row: spheres.
sphere { <-3.3, 1.7, 0>, 1.2
  pigment { rgb <1, 0.5, 0.4> } finish { Fin }
  normal { gradient y 1 slope_map { [0 <0, 1>] [0.5 <1, 1>] [1 <0, -1>] } scale 0.6 }
}
sphere { <0, 1.7, 0>, 1.2
  pigment { rgb <0.5, 1, 0.5> } finish { Fin }
  normal { onion 1 slope_map { Tri } scale 0.5 }
}
sphere { <3.3, 1.7, 0>, 1.2
  pigment { rgb <0.5, 0.6, 1> } finish { Fin }
  normal { radial 4 frequency 6 slope_map { [0 <0, 0>] [1 <1, 0>] } rotate x*90 }
}
// Bottom row: boxes facing the camera with other maps and wave types.
box { <-4.5, -2.9, -0.5>, <-2.1, -0.5, 0.5>
  pigment { rgb 0.9 } finish { Fin }
  normal { gradient x 1 triangle_wave slope_map { [0 <0, 1>] [0.5 <1, 1>] [1 <0, -1>] } scale 0.8 }
}
box { <-1.2, -2.9, -0.5>, <1.2, -0.5, 0.5>
  pigment { rgb <1, 1, 0.6> } finish { Fin }
  normal { gradient x 0.7 sine_wave frequency 2
    slope_map { [0.2 <0, 1>] [0.8 <1, 1>] } scale 1.5 }
}
box { <2.1, -2.9, -0.5>, <4.5, -0.5, 0.5>
  pigment { rgb <1, 0.8, 1> } finish { Fin }
  normal { gradient y 1 scallop_wave
    slope_map { [0 <0, 3>] [0.5 <1, 0>] [0.5 <0, 0>] [0.7 <0, 0>] [0.7 <1, 0>] [1 <1, 0>] }
    rotate z*30 scale 0.9 }
}

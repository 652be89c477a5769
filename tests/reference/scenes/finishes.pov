// Finishes beyond the chapter's: metallic highlights, variable and Fresnel reflection,
// reflection exponent and metallic reflection, emission, conserve_energy, albedo.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light rgb <0.8, 0.8, 1> }

camera { location <0, 3, -8> look_at <0, 0.9, 0> angle 55 }
light_source { <-5, 9, -7> color rgb 1 }
light_source { <6, 4, -3> color rgb <0.5, 0.45, 0.4> }
background { color rgb <0.25, 0.3, 0.45> }

plane { y, 0 pigment { checker color rgb <0.85, 0.8, 0.7> color rgb <0.15, 0.2, 0.3> } }
// Gold with metallic highlights.
sphere { <-2.6, 1, 0>, 1 pigment { color rgb <0.9, 0.65, 0.2> }
         finish { ambient 0.05 diffuse 0.5 phong 0.9 phong_size 30 specular 0.5 roughness 0.02 metallic } }
// Fresnel reflection over a dark glaze.
sphere { <0, 1, 0>, 1 pigment { color rgb <0.1, 0.2, 0.5> }
         finish { diffuse 0.6 reflection { 0.0, 1.0 fresnel on } } interior { ior 1.5 } }
// Variable reflection with falloff, exponent and metallic reflection.
sphere { <2.6, 1, 0>, 1 pigment { color rgb <0.8, 0.3, 0.25> }
         finish { diffuse 0.3 reflection { 0.1, 0.8 falloff 2 exponent 0.7 metallic 0.8 } } }
// A glowing box (emission ignores ambient_light) and an albedo diffuse with brilliance.
box { <-3.4, 0, 2>, <-2, 1.2, 3.2> pigment { color rgb <0.2, 0.8, 0.3> }
      finish { ambient 0 emission 0.6 diffuse 0.2 } }
sphere { <-0.6, 0.6, 2.6>, 0.6 pigment { color rgb 0.8 } finish { diffuse albedo 0.5 brilliance 3 } }
// conserve_energy: a reflective, transparent sphere transmits what reflection leaves.
sphere { <1.5, 0.7, 2.4>, 0.7 pigment { color rgbf <0.9, 0.9, 1, 0.8> }
         finish { reflection { 0.1, 0.9 } conserve_energy } interior { ior 1.3 } }

// Transforms as values: `matrix`, `transform { }` with declared transforms and `inverse`, in
// objects, pigments and macros (3.3.1.12).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -10> look_at <0, 0, 0> angle 40 }
light_source { <-10, 20, -30> rgb 1 }
#declare T1 = transform { rotate y*30 scale <1, 0.5, 1> translate x }
#declare T2 = transform { T1 translate y inverse }
#macro Sh() transform { matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 0, 0, 0> } #end
box { -1, 1 pigment { checker rgb 1, rgb <1,0,0> scale 0.5 transform T1 } transform T1 translate <-2.5, 0, 0> }
box { -1, 1 pigment { rgb <0.2, 0.6, 1> } Sh() }
cylinder { 0, y, 0.5 matrix <1, 0, 0, 0.5, 1, 0, 0, 0, 1, 2.5, 0, 0> pigment { rgb <0.3, 1, 0.3> } }
sphere { 0, 0.5 transform { T2 } translate <0, 0, -3> pigment { rgb 1 } }
sphere { 0, 0.5 transform { T1 inverse } translate <2, 1.5, -2> pigment { rgb <1,1,0> } }
plane { y, -1.5 pigment { checker rgb 0.2, rgb 0.8 } transform { rotate y*20 } }

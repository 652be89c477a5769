// quilted as a normal: POV-Ray 3.7 adds amount·(2/√3)·q(|v|)·v to the normal facing the ray
// (v the offset from the unit cube's centre), not the gradient of its pigment. Flat quads lit
// by one parallel light from the upper left, diffuse only.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
light_source { <0, 0, 0> rgb 1 parallel point_at <1, -1.5, 2> }

#declare F = finish { ambient 0.1 diffuse 0.9 }

#macro Tile(X, Y, N)
    box { <-1.9, -1.4, 0>, <1.9, 1.4, 0.1> texture { pigment { rgb <0.9, 0.85, 0.7> } normal { N } finish { F } } translate <X, Y, 0> }
#end

#declare N1 = normal { quilted 1 scale 0.5 translate <0, 0, 0.3> }
Tile(-2, 1.5, N1)
#declare N2 = normal { quilted 0.6 control0 0 control1 0 scale 0.4 translate <0.1, 0, 0.15> }
Tile(2, 1.5, N2)
#declare N3 = normal { quilted 0.8 control0 0 control1 1 scale 0.6 rotate <25, -20, 10> }
Tile(-2, -1.5, N3)
#declare N4 = normal { quilted 1.5 control0 0.5 control1 0.5 scale 0.35 translate <0, 0, 0.05> }
Tile(2, -1.5, N4)

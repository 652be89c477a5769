// Noise normals, one tile each, lit from the upper left, seen head-on in front of a plain wall:
// bumps, dents, wrinkles and bumps with turbulence, at a scale that puts several features in a
// 15×15-pixel window. Compared by region (tests/suite/reference.rs `check_regions`).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
light_source { <-30, 30, -40> color rgb 1 }

#declare F = finish { ambient 0.1 diffuse 0.9 }

plane { z, 0.5 pigment { rgb <0.3, 0.32, 0.35> } finish { F } }

#macro Tile(X, Y, N)
    box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.1> texture { pigment { rgb <0.9, 0.8, 0.6> } normal { N } finish { F } } translate <X, Y, 0> }
#end

Tile(-3, 1, normal { bumps 0.6 scale 0.06 })
Tile(-1, 1, normal { dents 0.8 scale 0.06 })
Tile(1, 1, normal { wrinkles 0.8 scale 0.08 })
Tile(3, 1, normal { bumps 0.5 turbulence 0.5 scale 0.08 })
Tile(-3, -1, normal { granite 0.4 scale 0.3 })
Tile(-1, -1, normal { marble 0.6 turbulence 0.8 scale 0.15 })
Tile(1, -1, normal { crackle 0.6 scale 0.1 })
Tile(3, -1, normal { leopard 0.8 scale 0.03 })

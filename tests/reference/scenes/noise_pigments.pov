// Noise pigments, one tile each, seen head-on with ambient light only (the pigment is what
// shows) in front of a plain wall. Compared by region (tests/suite/reference.rs `check_regions`):
// each tile's blurred colour and texture strength, the wall exactly. Scales put several
// features in a 15×15-pixel window (a tile is about 150 pixels wide).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }

#declare Map = color_map { [0 rgb <0.05, 0.1, 0.3>] [1 rgb <1, 0.85, 0.5>] }
#declare F = finish { ambient 1 diffuse 0 }

plane { z, 0.5 pigment { rgb <0.3, 0.32, 0.35> } finish { F } }

#macro Tile(X, Y, P)
    box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.1> texture { pigment { P } finish { F } } translate <X, Y, 0> }
#end

Tile(-3, 2, pigment { bozo color_map { Map } scale 0.06 })
Tile(-1, 2, pigment { spotted color_map { Map } scale 0.06 })
Tile(1, 2, pigment { granite color_map { Map } scale 0.3 })
Tile(3, 2, pigment { agate color_map { Map } scale 0.15 })
Tile(-3, 0, pigment { marble turbulence 0.8 color_map { Map } scale 0.15 })
Tile(-1, 0, pigment { wood turbulence 0.1 color_map { Map } scale 0.08 })
Tile(1, 0, pigment { crackle color_map { Map } scale 0.1 })
Tile(3, 0, pigment { leopard color_map { Map } scale 0.03 })
Tile(-3, -2, pigment { gradient x turbulence 0.6 color_map { Map } scale 0.15 })
Tile(-1, -2, pigment { gradient x turbulence 0.6 octaves 2 omega 0.8 lambda 3 color_map { Map } scale 0.15 })
Tile(1, -2, pigment { gradient x warp { turbulence 0.6 } color_map { Map } scale 0.15 })
Tile(3, -2, pigment { marble warp { turbulence <0.3, 0.6, 0> octaves 3 omega 0.6 lambda 2.5 } color_map { Map } scale 0.15 })

// Warps on exact patterns, flat quads seen head-on with ambient light only: repeat with
// offset and flip, two warps (the last written applies first), black_hole (falloff, strength,
// inverse, repeat), the mapping warps (cylindrical, spherical with orientation and dist_exp,
// planar with a normal, toroidal), each written after the transforms it works under.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare F = finish { ambient 1 diffuse 0 }
#declare Base = pigment { gradient <1, 1, 0> color_map { Map } scale 0.3 }

#macro Tile(X, Y, P)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { pigment { P } finish { F } } translate <X, Y, 0> }
#end

Tile(-3, 2, pigment { Base warp { repeat x * 0.4 } })
Tile(-1, 2, pigment { Base warp { repeat x * 0.5 offset <0, 0.13, 0> } })
Tile(1, 2, pigment { Base warp { repeat y * 0.45 flip y } })
Tile(3, 2, pigment { Base warp { repeat x * 0.35 offset <0.05, 0.1, 0> flip x } warp { repeat y * 0.6 } })
Tile(-3, 0, pigment { checker rgb <1, 0.9, 0.2> rgb <0.1, 0.2, 0.8> scale 0.2 warp { black_hole <0, 0, 0>, 0.8 } })
Tile(-1, 0, pigment { checker rgb <1, 0.9, 0.2> rgb <0.1, 0.2, 0.8> scale 0.2 warp { black_hole <0.1, 0.1, 0>, 0.7 falloff 3 strength 1.5 } })
Tile(1, 0, pigment { checker rgb <1, 0.9, 0.2> rgb <0.1, 0.2, 0.8> scale 0.2 warp { black_hole <0, 0, 0>, 0.8 strength 0.7 inverse } })
Tile(3, 0, pigment { checker rgb <1, 0.9, 0.2> rgb <0.1, 0.2, 0.8> scale 0.2 warp { black_hole <0, 0, 0>, 0.3 repeat <0.8, 0.8, 0> } })
Tile(-3, -2, pigment { checker rgb <1, 0.9, 0.2> rgb <0.1, 0.2, 0.8> scale <0.1, 0.27, 0.25> warp { cylindrical } translate z * 0.3 })
Tile(-1, -2, pigment { checker rgb <1, 0.9, 0.2> rgb <0.1, 0.2, 0.8> scale 0.25 warp { spherical orientation y dist_exp 1 } translate z * 0.4 })
Tile(1, -2, pigment { checker rgb <1, 0.9, 0.2> rgb <0.1, 0.2, 0.8> scale 0.25 rotate 20 * z warp { planar <0, 1, 1>, 0.6 } })
Tile(3, -2, pigment { gradient x color_map { Map } scale 0.1 warp { toroidal major_radius 0.6 dist_exp 1 } translate z * 0.2 })

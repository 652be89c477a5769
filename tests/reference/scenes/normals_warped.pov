// Pattern normals under warps, one tile each, lit from the upper left, seen head-on. POV-Ray
// 3.7 warps the point once and differentiates the unwarped pattern around it, so a turbulence
// warp or a black hole leaves the stripes' tilt as it was and `repeat` keeps the first cell's.
// Compared by region (tests/suite/reference.rs `check_regions`).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
light_source { <-30, 30, -40> color rgb 1 }

#declare F = finish { ambient 0.1 diffuse 0.9 }

plane { z, 0.5 pigment { rgb <0.3, 0.32, 0.35> } finish { F } }

#macro Tile(X, Y, N)
    box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.1> texture { pigment { rgb <0.9, 0.8, 0.6> } normal { N } finish { F } } translate <X, Y, 0> }
#end

Tile(-3, 1, normal { marble 0.6 warp { turbulence 0.8 } scale 0.15 })
Tile(-1, 1, normal { gradient x 1 triangle_wave warp { turbulence 0.8 } scale 0.25 })
Tile(1, 1, normal { bozo 1 warp { turbulence 0.5 } scale 0.1 })
Tile(3, 1, normal { gradient y 1 triangle_wave warp { turbulence 0.6 } warp { black_hole <0, 0, 0>, 1.5 strength 2 } scale 0.3 translate <3, 1, 0> })
Tile(-3, -1, normal { gradient x 1 triangle_wave warp { black_hole <0, 0, 0>, 1.5 strength 2 } scale 0.3 translate <-3, -1, 0> })
Tile(-1, -1, normal { gradient x 1 triangle_wave warp { repeat x * 0.3 flip x } scale 0.5 })
Tile(1, -1, normal { onion 0.8 sine_wave warp { turbulence 0.5 octaves 3 } scale 0.2 translate <1, -1, 0> })
Tile(3, -1, normal { wood 0.6 warp { turbulence 0.4 } scale 0.2 })

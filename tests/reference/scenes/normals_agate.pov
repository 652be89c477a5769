// agate as a normal, one tile each, lit from the upper left, seen head-on:
// bands along z shifted by marble's classic turbulence sum (patterns::turbulent::agate). The
// tilted tiles turn the bands to cross the view. Compared by region (tests/reference.rs
// `check_regions`).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
light_source { <-30, 30, -40> color rgb 1 }

#declare F = finish { ambient 0.1 diffuse 0.9 }

plane { z, 0.5 pigment { rgb <0.3, 0.32, 0.35> } finish { F } }

#macro Tile(X, Y, P, N)
    box { <-0.9, -0.9, 0>, <0.9, 0.9, 0.1> texture { pigment { P } normal { N } finish { F } } translate <X, Y, 0> }
#end

#declare Plain = pigment { rgb <0.9, 0.8, 0.6> }

Tile(-3, 1, Plain, normal { agate 0.6 scale 0.3 })
Tile(-1, 1, Plain, normal { agate 0.6 agate_turb 0.3 scale 0.2 })
Tile(1, 1, Plain, normal { agate 0.5 rotate x * 60 scale 0.4 })
Tile(3, 1, Plain, normal { agate 0.4 agate_turb 2 scale 0.5 })
Tile(-3, -1, Plain, normal { agate 0.8 scale 0.15 })
Tile(-1, -1, Plain, normal { agate 0.6 agate_turb 0.6 rotate y * 70 scale 0.25 })
Tile(1, -1, Plain, normal { agate 0.5 turbulence 0.5 scale 0.3 })
Tile(3, -1, Plain, normal { agate 0.6 agate_turb 0.5 slope_map { [0 <0, 1>] [1 <1, 1>] } scale 0.3 })

// `function { }` as a pattern (3.4.7.1.12): declared and inline user functions, an internal
// function of functions.inc (f_sphere), values beyond [0, 1] wrapped, a transformed function pigment, a
// function normal and a function selecting textures.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
light_source { <-10, 10, -30> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare F = finish { ambient 1 diffuse 0 }
#declare Wave = function(a, b) { sin(a * 3) * cos(b * 2) * 0.5 + 0.5 }

#macro Tile(X, Y, T)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { T } translate <X, Y, 0> }
#end

Tile(-3, 2, texture { pigment { function { Wave(x, y) } color_map { Map } } finish { F } })
Tile(-1, 2, texture { pigment { function { x * 1.5 } color_map { Map } } finish { F } })
Tile(1, 2, texture { pigment { function { f_sphere(x, y, z, 0.2) } color_map { Map } scale 0.6 } finish { F } })
Tile(3, 2, texture { pigment { function { abs(x) + abs(y) } sine_wave frequency 2 color_map { Map } rotate z*30 } finish { F } })
Tile(-3, 0, texture { pigment { function { x*x - y } color_map { Map } translate <0.2, 0.3, 0> } finish { F } })
Tile(-1, 0, texture { pigment { rgb <0.9, 0.8, 0.6> } normal { function { Wave(x, y) } 0.5 } finish { ambient 0.2 diffuse 0.8 } })
Tile(1, 0, texture { pigment { function { select(x, 0.2, 0.8) } color_map { Map } } finish { F } })
Tile(3, 0, texture { function { Wave(x, y * 2) } texture_map {
    [0.4 pigment { rgb <0.1, 0.5, 0.2> } finish { F }]
    [0.6 pigment { rgb <0.9, 0.9, 0.9> } finish { F }] } })
Tile(-2, -2, texture { pigment { function { atan2(y, x) / (2 * pi) } color_map { Map } } finish { F } })
Tile(0, -2, texture { pigment { function { sqrt(x*x + y*y) } color_map { Map } scale 0.3 } finish { F } })
Tile(2, -2, texture { pigment { function { max(x, y) + 0.5 } triangle_wave color_map { Map } scale 0.5 } finish { F } })

// Fractal patterns (mandel, julia, magnet 1|2 with exponents and interior/exterior types)
// and pigment_pattern (a pigment's grey as a pattern) on flat quads seen head-on, ambient only.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare F = finish { ambient 1 diffuse 0 }

#macro Tile(X, Y, P)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { pigment { P } finish { F } } translate <X, Y, 0> }
#end

#declare P1 = pigment { mandel 12 color_map { Map } translate x * 0.5 scale 0.45 }
Tile(-3, 2, P1)
#declare P2 = pigment { julia <0.353, 0.288>, 15 interior 1, 1 color_map { Map } scale 0.6 }
Tile(-1, 2, P2)
#declare P3 = pigment { mandel 10 exponent 3 interior 6, 0.5 exterior 2, 0.3 color_map { Map } scale 0.6 }
Tile(1, 2, P3)
#declare P4 = pigment { magnet 1 mandel 20 color_map { Map } translate <-0.2, 0, 0> scale 0.35 }
Tile(3, 2, P4)
#declare P5 = pigment { magnet 2 julia <0.4, 0.3>, 20 exterior 6, 0.2 color_map { Map } scale 0.4 }
Tile(-3, 0, P5)
#declare P6 = pigment { pigment_pattern { checker rgb <1, 0, 0> rgb <0.2, 0.9, 0.4> scale 0.5 } color_map { Map } }
Tile(-1, 0, P6)
#declare P7 = pigment { pigment_pattern { gradient x color_map { [0 rgb 0] [1 rgb <0, 1, 1>] } scale 0.5 }
    pigment_map { [0 rgb <1, 0.5, 0>] [1 checker rgb 0 rgb 1 scale 0.25] } }
Tile(1, 0, P7)
#declare P8 = pigment { mandel 15 exponent 4 exterior 1, 1 interior 0, 1 color_map { Map } scale 0.6 }
Tile(3, 0, P8)
#declare P9 = pigment { julia <-0.5, 0.5>, 10 exponent 4 interior 4, 2 color_map { Map } scale 0.7 }
Tile(-3, -2, P9)
#declare P10 = pigment { mandel 25 exterior 7, 5 color_map { Map } translate x * 0.5 scale 0.45 }
Tile(-1, -2, P10)
#declare P11 = pigment { mandel 25 exterior 8, 5 color_map { Map } translate x * 0.5 scale 0.45 }
Tile(1, -2, P11)
#declare P12 = pigment { pigment_pattern { onion color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } scale 0.4 } poly_wave 2 color_map { Map } }
Tile(3, -2, P12)

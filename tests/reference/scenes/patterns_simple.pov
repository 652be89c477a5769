// Exact patterns of the kernel layer with colour maps, waves, frequency and phase, on flat
// quads seen head-on (ambient only, so the pigment is what shows).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare F = finish { ambient 1 diffuse 0 }

#macro Tile(X, Y, P)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { pigment { P } finish { F } } translate <X, Y, 0> }
#end

#declare P1 = pigment { gradient x color_map { Map } scale 0.5 }
Tile(-3, 2, P1)
#declare P2 = pigment { gradient <1, 1, 0> triangle_wave color_map { Map } scale 0.7 }
Tile(-1, 2, P2)
#declare P3 = pigment { onion color_map { Map } scale 0.4 }
Tile(1, 2, P3)
#declare P4 = pigment { radial frequency 6 color_map { Map } rotate x * -90 }
Tile(3, 2, P4)
#declare P5 = pigment { brick color rgb 0.9 color rgb <0.7, 0.2, 0.1> brick_size <0.5, 0.25, 0.5> mortar 0.05 }
Tile(-3, 0, P5)
#declare P6 = pigment { hexagon color rgb <1, 0, 0> color rgb <0, 1, 0> color rgb <0, 0, 1> scale 0.2 rotate x * -90 }
Tile(-1, 0, P6)
#declare P7 = pigment { checker pigment { gradient y color_map { Map } scale 0.25 } pigment { rgb 0.2 } scale 0.5 }
Tile(1, 0, P7)
#declare P8 = pigment { boxed sine_wave color_map { Map } translate <0.1, 0.1, 0> }
Tile(3, 0, P8)
#declare P9 = pigment { spherical scallop_wave frequency 3 color_map { Map } }
Tile(-3, -2, P9)
#declare P10 = pigment { cylindrical cubic_wave color_map { Map } rotate x * 90 }
Tile(-1, -2, P10)
#declare P11 = pigment { planar poly_wave 2 phase 0.3 color_map { Map } }
Tile(1, -2, P11)
#declare P12 = pigment { gradient y pigment_map { [0 rgb <1, 1, 1>] [1 checker rgb 0 rgb 1 scale 0.2] } }
Tile(3, -2, P12)

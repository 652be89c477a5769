// quilted with several control0/control1 pairs and spiral2 with several arm counts and waves,
// on flat quads seen head-on (ambient only, so the pigment is what shows). Both are exact
// patterns (no noise); strahl's kernels were fitted to POV-Ray 3.7's values.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare Grey = color_map { [0 rgb 0] [1 rgb 1] }
#declare F = finish { ambient 1 diffuse 0 }

#macro Tile(X, Y, P)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { pigment { P } finish { F } } translate <X, Y, 0> }
#end

// quilted: the default controls (1, 1), then (0, 0), (0.5, 0.5), (-1, 2); the face z = 0 lies
// on a cell face, so the first ones are moved along z to show a cut through the cells.
#declare P1 = pigment { quilted color_map { Grey } scale 0.5 translate <0, 0, 0.2> }
Tile(-3, 2, P1)
#declare P2 = pigment { quilted control0 0 control1 0 color_map { Grey } scale 0.4 translate <0.1, 0, 0.15> }
Tile(-1, 2, P2)
#declare P3 = pigment { quilted control0 0.5 control1 0.5 color_map { Map } scale 0.6 }
Tile(1, 2, P3)
#declare P4 = pigment { quilted control0 -1 control1 2 color_map { Map } scale 0.5 rotate <20, 30, 0> }
Tile(3, 2, P4)
// (0, 1) and (1, 0), a frequency, and controls (5, 5) whose corners pass 1 (the map clamps).
#declare P5 = pigment { quilted control0 0 control1 1 color_map { Map } scale 0.3 rotate z * 15 }
Tile(-3, 0, P5)
#declare P6 = pigment { quilted control0 1 control1 0 color_map { Grey } scale 0.45 translate <0, 0, 0.3> }
Tile(-1, 0, P6)
#declare P7 = pigment { quilted frequency 2 color_map { Map } scale 0.7 translate <0.2, 0.1, 0.25> }
Tile(1, 0, P7)
#declare P8 = pigment { quilted control0 5 control1 5 color_map { Grey } scale 0.5 translate <0, 0, 0.1> }
Tile(3, 0, P8)
// spiral2: its default triangle wave with 2 and 5 arms, a ramp_wave, and a sine_wave on a
// tilted plane (z varies across the tile).
#declare P9 = pigment { spiral2 2 color_map { Map } scale 0.3 }
Tile(-3, -2, P9)
#declare P10 = pigment { spiral2 5 color_map { Grey } scale 0.4 }
Tile(-1, -2, P10)
#declare P11 = pigment { spiral2 3 ramp_wave color_map { Map } scale 0.35 translate <0.1, -0.1, 0.2> }
Tile(1, -2, P11)
#declare P12 = pigment { spiral2 1 sine_wave color_map { Map } scale 0.3 rotate x * 40 }
Tile(3, -2, P12)

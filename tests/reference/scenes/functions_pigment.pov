// Pattern and pigment functions (3.3.1.8.5): a pigment function read channel by channel in
// function patterns (the gamma macro of POV-Ray's woods samples, with `average` entries that
// leave out their weight), `.gray`, pattern functions of checker, onion and gradient, and a
// height field made from a function image.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
light_source { <-10, 10, -30> rgb 1 }

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare F = finish { ambient 1 diffuse 0 }

#macro Tile(X, Y, T)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { T } translate <X, Y, 0> }
#end

#macro Gamma(Orig, G)
  #local Fn = function { pigment { Orig } }
  pigment { average pigment_map {
    [function { pow(Fn(x, y, z).x, G) } color_map { [0 rgb 0] [1 rgb <3, 0, 0>] }]
    [function { pow(Fn(x, y, z).y, G) } color_map { [0 rgb 0] [1 rgb <0, 3, 0>] }]
    [function { pow(Fn(x, y, z).z, G) } color_map { [0 rgb 0] [1 rgb <0, 0, 3>] }]
  } }
#end

#declare Checks = function { pigment { boxed color_map { [0 rgb <0.9, 0.2, 0.1>] [1 rgb <0.1, 0.3, 0.9>] } scale 0.8 } }
#declare Rings = function { pattern { onion scale 0.6 } }
#declare Ramp = function { pattern { gradient x scale 0.7 } }
#declare Hue = function { pigment { gradient y color_map { Map } scale 2 translate -y } }

Tile(-3, 2, texture { Gamma(pigment { gradient x color_map { Map } translate -0.5 * x }, 2.0) finish { F } })
Tile(-1, 2, texture { pigment { function { Checks(x, y, z).red } color_map { Map } } finish { F } })
Tile(1, 2, texture { pigment { function { Rings(x, y, z) * 0.9 } color_map { Map } } finish { F } })
Tile(3, 2, texture { pigment { function { Hue(x, y, z).gray } color_map { Map } } finish { F } })
Tile(-3, 0, texture { pigment { function { Ramp(x, y, z) * Checks(x, y, z).blue } color_map { Map } } finish { F } })
Tile(-1, 0, texture { pigment { function { abs(Hue(x, y, z).red - Hue(x, y, z).blue) } color_map { Map } } finish { F } })

height_field {
  function 64, 64 { pattern { spherical scale 0.5 translate <0.5, 0.5, 0> } }
  smooth
  translate <-0.5, 0, -0.5>
  scale <1.9, 0.8, 1.9>
  rotate -60 * x
  translate <2, -0.5, 0>
  pigment { rgb <0.9, 0.7, 0.4> }
  finish { ambient 0.2 diffuse 0.8 }
}

// image_map (planar, repeated, once, interpolate 2, spherical, cylindrical, torus, palette
// filter/transmit) and image_pattern, on a 16×16 test image (tests/reference/images), ambient
// only so the pigment is what shows.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
background { rgb <0.2, 0.3, 0.25> }

#declare F = finish { ambient 1 diffuse 0 }
#declare Img = "../images/test16.png"

#macro Tile(X, Y, P)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { pigment { P } finish { F } } translate <X, Y, 0> }
#end

// Planar, one copy over the tile.
Tile(-3, 2, pigment { image_map { png Img } translate -0.5 scale 1.9 })
// Repeated 2×2 and rotated.
Tile(-1, 2, pigment { image_map { png Img } scale 0.95 rotate z * 20 })
// Bilinear.
Tile(1, 2, pigment { image_map { png Img interpolate 2 } translate -0.5 scale 1.9 })
// Bilinear, repeated and turned.
Tile(3, 2, pigment { image_map { png Img interpolate 2 } rotate z * 45 scale 0.6 })
// once: outside is clear, the magenta behind shows.
box { <-0.95, -0.95, 0.2>, <0.95, 0.95, 0.3> pigment { rgb <1, 0, 1> } finish { F } translate <-3, 0, 0> }
Tile(-3, 0, pigment { image_map { png Img once } scale 1.2 translate <-0.6, -0.6, 0> })
// Palette image: entry 1 filtered, entry 2 transmitted, over yellow.
box { <-0.95, -0.95, 0.2>, <0.95, 0.95, 0.3> pigment { rgb <1, 1, 0.2> } finish { F } translate <-1, 0, 0> }
Tile(-1, 0, pigment { image_map { png "../images/pal8.png" filter 1, 0.8 transmit 2 0.6 } translate -0.5 scale 1.9 })
// image_pattern through a colour map.
Tile(1, 0, pigment { image_pattern { png "../images/bump16.png" interpolate 2 }
    color_map { [0 rgb <0.1, 0.1, 0.6>] [1 rgb <1, 0.8, 0.2>] } translate -0.5 scale 1.9 })
// Transmit all.
Tile(3, 0, pigment { image_map { png Img transmit all 0.5 } translate -0.5 scale 1.9 })
box { <-0.95, -0.95, 0.2>, <0.95, 0.95, 0.3> pigment { rgb <0, 0, 0> } finish { F } translate <3, 0, 0> }

// Spherical, cylindrical and torus maps.
sphere { 0, 0.9 texture { pigment { image_map { png Img map_type 1 } } finish { F } } rotate y * 30 translate <-3, -2, 0> }
cylinder { <0, -0.9, 0>, <0, 0.9, 0>, 0.8 texture { pigment { image_map { png Img map_type 2 } scale <1, 1.8, 1> translate -0.9 * y } finish { F } } rotate y * 20 translate <-1, -2, 0> }
torus { 0.6, 0.3 texture { pigment { image_map { png Img map_type 5 interpolate 2 } scale 0.6 } finish { F } } rotate x * -60 translate <1, -2, 0> }
sphere { 0, 0.9 texture { pigment { image_map { png Img map_type 1 interpolate 2 } } finish { F } } rotate x * 50 translate <3, -2, 0> }

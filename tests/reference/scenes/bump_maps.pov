// bump_map: a grey disc image as heights on flat tiles lit from the side (diffuse only), with
// bump_size, interpolate, a colour image's intensity, repeated and rotated.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }
light_source { <-30, 30, -40> rgb 1 }
background { rgb 0.1 }

#declare F = finish { ambient 0.1 diffuse 0.9 }

#macro Tile(X, Y, N)
    box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1> texture { pigment { rgb 0.8 } normal { N } finish { F } } translate <X, Y, 0> }
#end

Tile(-3, 1, normal { bump_map { png "../images/bump16.png" } translate -0.5 scale 1.9 })
Tile(-1, 1, normal { bump_map { png "../images/bump16.png" bump_size 3 } translate -0.5 scale 1.9 })
Tile(1, 1, normal { bump_map { png "../images/bump16.png" interpolate 2 bump_size 2 } translate -0.5 scale 1.9 })
Tile(3, 1, normal { bump_map { png "../images/bump16.png" bump_size -2 } translate -0.5 scale 0.95 })
Tile(-3, -1, normal { bump_map { png "../images/test16.png" bump_size 2 } translate -0.5 scale 1.9 })
Tile(-1, -1, normal { bump_map { png "../images/bump16.png" interpolate 2 bump_size 0.5 } scale 0.6 })
Tile(1, -1, normal { bump_map { png "../images/test16.png" use_color interpolate 2 } translate -0.5 scale 1.9 })
Tile(3, -1, normal { bump_map { png "../images/bump16.png" bump_size 1 } translate -0.5 scale 1.9 rotate z * 30 })

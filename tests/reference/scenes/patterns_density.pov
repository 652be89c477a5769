// density_file df3 patterns (8-bit and 16-bit voxels, interpolate 0 and 1) on flat quads
// seen head-on, ambient only; voxels.df3 and voxels16.df3 are made by a few lines of Python
// (8×6×2 bytes (37i + 53j + 101k) mod 256; 4×4×1 u16 (20000i + 5000j) mod 65536).
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0, -20> look_at <0, 0, 0> angle 22.62 }

#declare Map = color_map { [0 rgb <0.1, 0.2, 0.8>] [0.5 rgb <1, 0.9, 0.2>] [1 rgb <0.8, 0.1, 0.1>] }
#declare F = finish { ambient 1 diffuse 0 }

#macro Tile(X, Y, P)
    box { <-1.45, -1.45, 0>, <1.45, 1.45, 0.1> texture { pigment { P } finish { F } } translate <X, Y, 0> }
#end

Tile(-1.5, 1.5, pigment { density_file df3 "voxels.df3" interpolate 0 color_map { Map } translate <-0.5, -0.5, -0.3> scale 2.6 })
Tile(1.5, 1.5, pigment { density_file df3 "voxels.df3" interpolate 1 color_map { Map } translate <-0.5, -0.5, -0.8> scale 2.6 })
Tile(-1.5, -1.5, pigment { density_file df3 "voxels16.df3" color_map { Map } translate <-0.5, -0.5, -0.5> scale 2.6 })
Tile(1.5, -1.5, pigment { density_file df3 "voxels16.df3" interpolate 1 color_map { Map } translate <-0.5, -0.5, -0.5> scale 2.6 })

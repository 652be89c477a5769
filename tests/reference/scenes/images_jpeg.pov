// JPEG images: an image_map of a photograph-like JPEG (test16.jpg, the PNG test image saved by
// Pillow) planar and interpolated, and a height_field from a grey JPEG stored as RGB.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 3, -7> look_at <0, 0.4, 0> angle 50 }
light_source { <-4, 8, -6> color rgb 1 }
background { rgb <0.2, 0.3, 0.25> }

#declare F = finish { ambient 1 diffuse 0 }
box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1>
    texture { pigment { image_map { jpeg "../images/test16.jpg" } translate -0.5 scale 1.9 } finish { F } }
    translate <-2.2, 1.6, 0> }
box { <-0.95, -0.95, 0>, <0.95, 0.95, 0.1>
    texture { pigment { image_map { "../images/test16.jpg" interpolate 2 } translate -0.5 scale 1.9 } finish { F } }
    translate <2.2, 1.6, 0> }
height_field { jpeg "../images/hill.jpg"
    translate <-0.5, 0, -0.5> scale <4, 1.2, 4>
    pigment { gradient y color_map { [0 rgb <0.2, 0.5, 0.2>] [1 rgb <0.9, 0.9, 0.8>] } scale 1.4 translate -0.1 * y }
    finish { ambient 0.2 diffuse 0.8 }
    translate <0, -0.6, 0> }

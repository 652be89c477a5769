// Polynomial surfaces around @P at scale @s(1), moved and scaled into place: an unbounded
// quadric cylinder and paraboloid (outside the BVH), an ellipsoid quadric (bounded), a quartic
// torus around the x axis (fast solver) and a rounded cube x^4 + y^4 + z^4 - 1 (sturm).
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location @p(0, 2.5, -6)
    look_at @p(0, 1, 0)
    angle 55
}

light_source { @p(-4, 6, -5) color White }
light_source { @p(4, 3, -6) color rgb 0.4 }
background { color rgb <0.2, 0.25, 0.4> }

plane {
    y, @py(0)
    pigment { checker color rgb 0.8 color rgb 0.3 scale @s(1) translate @P }
}

quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -0.09 scale @s(1) translate @p(2.2, 0, 1) pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
quadric { <1, 0, 1>, <0, 0, 0>, <0, -1, 0>, 0 scale @s(0.5) translate @p(-2.2, 0, 1.5) pigment { color rgb <0.2, 0.6, 1> } }
quadric { <1, 4, 1>, <1, 0, 0>, <0, 0, 0>, -1 scale @s(0.6) translate @p(0.8, 0.5, -1.5) pigment { color rgb <0.3, 0.9, 0.4> } finish { phong 0.4 } }
quartic { <1, 0, 0, 0, 2, 0, 0, 2, 0, 1.755, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 2, 0, -2.245, 0, 0, 0, 0, 1, 0, -2.245, 0, 0.77000625> rotate y*30 scale @s(0.8) translate @p(-0.8, 0.9, -0.5) pigment { color rgb <1, 0.6, 0.2> } finish { phong 0.5 } }
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1, 0, 0, 0, -1> sturm rotate <20, 30, 0> scale @s(0.5) translate @p(0.6, 1.8, 1) pigment { color rgb <0.4, 0.7, 1> } }

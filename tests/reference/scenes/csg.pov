// CSG as POV-Ray does it: intersection, difference, merge (no inner surfaces through glass),
// inverse, clipped_by, a union nested in a difference, planes as half-spaces, and textures on
// the CSG reaching the children without one (also through a declared object).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.6, 0> angle 52 }
light_source { <6, 10, -7> color rgb 1 }
light_source { <-6, 6, -3> color rgb 0.4 }
plane { y, -1 pigment { checker color rgb 0.85 color rgb 0.35 } }

// A cube with a sphere cut out, and a union of two cylinders drilled through it.
difference {
  box { <-1, -1, -1>, <1, 1, 1> pigment { rgb <1, 0.35, 0.2> } }
  sphere { 0, 1.3 pigment { rgb <0.2, 0.5, 1> } }
  union {
    cylinder { <0, 0, -2>, <0, 0, 2>, 0.3 }
    cylinder { <-2, 0, 0>, <2, 0, 0>, 0.3 }
    pigment { rgb <1, 0.9, 0.2> }
  }
  rotate 25*y
  translate <-2.4, 0, 0.5>
}

// A bowl: a sphere cut by a plane, hollowed by an inverse cylinder.
#declare Bowl = intersection {
  sphere { 0, 1 }
  cylinder { -2*y, 2*y, 0.65 inverse }
  plane { y, 0.45 }
}
object { Bowl pigment { rgb <0.3, 0.85, 0.35> } finish { phong 0.6 } translate <0, 0, 1.6> }

// Glass merge: two overlapping spheres without their inner surfaces.
merge {
  sphere { <-0.45, 0, 0>, 0.75 }
  sphere { <0.45, 0, 0>, 0.75 }
  pigment { rgbf <0.9, 0.95, 1, 0.85> }
  finish { phong 0.8 }
  interior { ior 1.45 }
  translate <2.5, -0.2, 0.4>
}

// A clipped sphere and an intersection of boxes with a rotated one.
sphere { <0, 0, 0>, 0.8 pigment { rgb 1 } clipped_by { plane { x, 0.25 } } translate <0.4, -0.2, -1.6> }
intersection {
  box { -0.7, 0.7 }
  box { -0.7, 0.7 rotate <45, 45, 0> }
  pigment { rgb <0.8, 0.4, 0.9> }
  translate <2.3, -0.3, -2>
}
difference {
  cone { <0, -1, 0>, 0.8, <0, 0.6, 0>, 0.1 }
  torus { 0.5, 0.25 translate 0.2*y }
  pigment { rgb <0.95, 0.75, 0.4> }
  translate <-2.2, 0, -2.2>
}

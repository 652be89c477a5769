// Kernel benchmark: quadric, a tilted ellipsoid x^2 + 2.5y^2 + z^2 + xy = 0.16, with bounded_by.
#version 3.7;
#include "kernel_common.inc"
KGrid(quadric { <1, 2.5, 1>, <1, 0, 0>, <0, 0, 0>, -0.16
  bounded_by { box { <-0.45, -0.45, -0.45>, <0.45, 0.45, 0.45> } }
  translate y * 0.45 })

// Kernel benchmark: poly of order 6, x^6 + y^6 + z^6 = 1 (a rounded cube; POV-Ray solves order 6
// with Sturm sequences), with bounded_by. The 84 coefficients: x^6 first, y^6 57th, z^6 78th,
// the constant last.
#version 3.7;
#include "kernel_common.inc"
KGrid(poly { 6, <
    1, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 1, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    0, 0, 0, 0, 0, 0, 0, 1, 0, 0,
    0, 0, 0, -1 >
  bounded_by { box { -1.01, 1.01 } }
  scale 0.38 translate y * 0.38 })

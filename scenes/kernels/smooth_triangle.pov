// Kernel benchmark: smooth_triangle, the triangle of triangle.pov with normals bent outwards.
#version 3.7;
#include "kernel_common.inc"
KGrid(smooth_triangle {
  <-0.45, 0, 0>, <-0.5, 0, -1>, <0.45, 0, 0>, <0.5, 0, -1>, <0, 0.9, 0>, <0, 0.5, -1>
  rotate <20, 30, 0> })

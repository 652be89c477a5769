// Kernel benchmark: prism, linear_sweep, quadratic_spline (the star of prism_linear.pov; the first
// point is a control point, the second and the last are the same).
#version 3.7;
#include "kernel_common.inc"
KGrid(prism { quadratic_spline linear_sweep 0, 0.6, 10,
  <0.12, -0.12>,
  <0.45, 0>, <0.12, 0.12>, <0, 0.45>, <-0.12, 0.12>, <-0.45, 0>, <-0.12, -0.12>, <0, -0.45>,
  <0.12, -0.12>, <0.45, 0> })

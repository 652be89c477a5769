// Kernel benchmark: prism, linear_sweep, cubic_spline (the star of prism_linear.pov; the first and
// last points are control points).
#version 3.7;
#include "kernel_common.inc"
KGrid(prism { cubic_spline linear_sweep 0, 0.6, 11,
  <0.12, -0.12>,
  <0.45, 0>, <0.12, 0.12>, <0, 0.45>, <-0.12, 0.12>, <-0.45, 0>, <-0.12, -0.12>, <0, -0.45>,
  <0.12, -0.12>, <0.45, 0>,
  <0.12, 0.12> })

// Kernel benchmark: lathe with quadratic_spline (the vase of lathe_linear.pov; the first point
// is a control point).
#version 3.7;
#include "kernel_common.inc"
KGrid(lathe { quadratic_spline 7,
  <0, -0.1>, <0, 0>, <0.45, 0>, <0.3, 0.4>, <0.45, 0.75>, <0.25, 0.95>, <0, 0.95> })

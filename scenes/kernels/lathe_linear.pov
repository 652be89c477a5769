// Kernel benchmark: lathe with linear_spline (a vase profile, 6 points).
#version 3.7;
#include "kernel_common.inc"
KGrid(lathe { linear_spline 6,
  <0, 0>, <0.45, 0>, <0.3, 0.4>, <0.45, 0.75>, <0.25, 0.95>, <0, 0.95> })

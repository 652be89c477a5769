// Kernel benchmark: prism, linear_sweep, linear_spline (a four-pointed star, 8 corners).
#version 3.7;
#include "kernel_common.inc"
KGrid(prism { linear_spline linear_sweep 0, 0.6, 9,
  <0.45, 0>, <0.12, 0.12>, <0, 0.45>, <-0.12, 0.12>, <-0.45, 0>, <-0.12, -0.12>, <0, -0.45>,
  <0.12, -0.12>, <0.45, 0> })

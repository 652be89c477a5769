// Kernel benchmark: prism, linear_sweep, bezier_spline (a four-petalled outline: four segments of
// four points, each ending where the next starts).
#version 3.7;
#include "kernel_common.inc"
KGrid(prism { bezier_spline linear_sweep 0, 0.6, 16,
  <0.45, 0>, <0.45, 0.3>, <0.3, 0.45>, <0, 0.45>,
  <0, 0.45>, <-0.1, 0.1>, <-0.1, 0.1>, <-0.45, 0>,
  <-0.45, 0>, <-0.45, -0.3>, <-0.3, -0.45>, <0, -0.45>,
  <0, -0.45>, <0.1, -0.1>, <0.1, -0.1>, <0.45, 0> })

// Kernel benchmark: lathe with bezier_spline (a vase: three segments of four points).
#version 3.7;
#include "kernel_common.inc"
KGrid(lathe { bezier_spline 12,
  <0, 0>, <0.2, 0>, <0.4, 0>, <0.45, 0.05>,
  <0.45, 0.05>, <0.1, 0.4>, <0.65, 0.7>, <0.3, 0.95>,
  <0.3, 0.95>, <0.2, 0.95>, <0.1, 0.95>, <0, 0.95> })

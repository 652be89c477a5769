// Kernel benchmark: sor (surface of revolution; always a cubic spline, first and last points
// are control points).
#version 3.7;
#include "kernel_common.inc"
KGrid(sor { 6, <0, -0.1>, <0.4, 0>, <0.25, 0.35>, <0.45, 0.7>, <0.3, 0.95>, <0.3, 1.05> })

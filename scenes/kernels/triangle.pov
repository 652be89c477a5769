// Kernel benchmark: triangle, one per cell, standing, turned 20 degrees about x and 30 about y.
#version 3.7;
#include "kernel_common.inc"
KGrid(triangle { <-0.45, 0, 0>, <0.45, 0, 0>, <0, 0.9, 0> rotate <20, 30, 0> })

// Kernel benchmark: cone (capped), upright, base radius 0.45, top radius 0.1.
#version 3.7;
#include "kernel_common.inc"
KGrid(cone { <0, 0, 0>, 0.45, <0, 0.9, 0>, 0.1 })

// Kernel benchmark: superellipsoid <0.3, 0.3> (a rounded cube).
#version 3.7;
#include "kernel_common.inc"
KGrid(superellipsoid { <0.3, 0.3> scale 0.4 translate y * 0.4 })

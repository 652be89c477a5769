// Kernel benchmark: disc, radius 0.45, tilted to face the camera.
#version 3.7;
#include "kernel_common.inc"
KGrid(disc { <0, 0.5, 0>, <0, 0.6, -1>, 0.45 })

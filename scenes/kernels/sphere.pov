// Kernel benchmark: sphere. 8x8 spheres on the floor (scripts/compare_kernels.sh).
#version 3.7;
#include "kernel_common.inc"
KGrid(sphere { <0, 0.5, 0>, 0.5 })

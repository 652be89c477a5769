// Kernel benchmark: difference of 8 children: a block minus 7 spheres, in each of the 64 cells (kernel_csg.inc).
#version 3.7;
#include "kernel_common.inc"
#include "kernel_csg.inc"
KGrid(difference { KDented(8) })

// Kernel benchmark: difference of 64 children: a block minus 63 spheres, in each of the 64 cells (kernel_csg.inc).
#version 3.7;
#include "kernel_common.inc"
#include "kernel_csg.inc"
KGrid(difference { KDented(64) })

// Kernel benchmark: union of 2 children: 2 overlapping spheres, in each of the 64 cells (kernel_csg.inc).
// (strahl flattens a union into its children in the BVH: the tests counted are the spheres'.)
#version 3.7;
#include "kernel_common.inc"
#include "kernel_csg.inc"
KGrid(union { KBalls(2) })

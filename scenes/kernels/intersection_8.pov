// Kernel benchmark: intersection of 8 children: 8 turned cubes (a convex polyhedron), in each of the 64 cells (kernel_csg.inc).
#version 3.7;
#include "kernel_common.inc"
#include "kernel_csg.inc"
KGrid(intersection { KCubes(8) })

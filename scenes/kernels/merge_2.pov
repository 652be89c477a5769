// Kernel benchmark: merge of 2 children: 2 overlapping spheres, in each of the 64 cells (kernel_csg.inc).
// (An opaque merge looks like a union; strahl flattens it into one, POV-Ray keeps the node.)
#version 3.7;
#include "kernel_common.inc"
#include "kernel_csg.inc"
KGrid(merge { KBalls(2) })

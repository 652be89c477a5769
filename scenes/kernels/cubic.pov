// Kernel benchmark: cubic, the monkey saddle y = x^3 - 3xz^2. A cubic surface is unbounded, so
// (as POV-Ray's sample quartic/monkey.pov does) each is an intersection with a box: the solid
// under the saddle. The tests counted are the CSG node's (strahl counts a CSG's children inside
// its node).
#version 3.7;
#include "kernel_common.inc"
KGrid(intersection {
  cubic { <-1, 0, 0, 0, 0, 0, 0, 3, 0, 0,
            0, 0, 0, 0, 0, 1, 0, 0, 0, 0> }
  box { -1, 1 }
  bounded_by { box { -1, 1 } }
  scale 0.4 translate y * 0.4 })

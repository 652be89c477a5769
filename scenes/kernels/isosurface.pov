// Kernel benchmark: isosurface, a sphere with a ripple (function of x, y, z only, no
// functions.inc), contained_by a box.
#version 3.7;
#include "kernel_common.inc"
KGrid(isosurface {
  function { sqrt(x * x + y * y + z * z) - 0.38 + 0.03 * sin(20 * x) * sin(20 * y) * sin(20 * z) }
  contained_by { box { -0.45, 0.45 } }
  max_gradient 2.2
  translate y * 0.45 })

// Kernel benchmark: quartic, a torus (major radius 1, minor 0.35, scaled to the torus of
// torus.pov) written as (x^2+y^2+z^2+k)^2 = 4(x^2+z^2), k = 1 - 0.35^2, with sturm and bounded_by.
#version 3.7;
#include "kernel_common.inc"
KGrid(quartic {
  < 1, 0, 0, 0, 2, 0, 0, 2, 0, -2.245,
    0, 0, 0, 0, 0, 0, 0, 0, 0, 0,
    1, 0, 0, 2, 0, 1.755, 0, 0, 0, 0,
    1, 0, -2.245, 0, 0.77000625 >
  sturm
  bounded_by { box { <-1.4, -0.4, -1.4>, <1.4, 0.4, 1.4> } }
  scale 0.35 translate y * 0.1225 })

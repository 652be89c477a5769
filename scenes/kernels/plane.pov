// Kernel benchmark: plane. A plane is infinite, so no grid: the floor and 63 more planes
// under it (y = -0.01 ... -0.63), all unbounded, so every ray tests all 64. The picture is the
// floor alone; tests per ray counts the Plane row.
// stats: Plane
#version 3.7;
#include "kernel_common.inc"
#declare I = 1;
#while (I < 64)
  plane { y, -0.01 * I texture { KTex } }
  #declare I = I + 1;
#end

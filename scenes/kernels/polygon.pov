// Kernel benchmark: polygon, a five-pointed star (10 corners, closed), standing, turned 20
// degrees about x towards the camera.
#version 3.7;
#include "kernel_common.inc"
#declare Star = polygon { 11
  #for (K, 0, 10)
    (K / 2 = int(K / 2) ? 0.45 : 0.18) * <sin(2 * pi * K / 10), cos(2 * pi * K / 10), 0>
  #end
}
KGrid(object { Star rotate x * 20 translate y * 0.45 })

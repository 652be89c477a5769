// Kernel benchmark: mesh, a UV sphere of radius 0.45, 32 segments x 16 rings (992 flat
// triangles), declared once and placed 64 times.
#version 3.7;
#include "kernel_common.inc"
#declare NU = 32;
#declare NV = 16;
#macro P(I, J) (0.45 * <sin(pi * J / NV) * cos(2 * pi * I / NU), -cos(pi * J / NV), sin(pi * J / NV) * sin(2 * pi * I / NU)>) #end
#declare Ball = mesh {
  #declare J = 0;
  #while (J < NV)
    #declare I = 0;
    #while (I < NU)
      #if (J > 0) triangle { P(I, J), P(I + 1, J), P(I + 1, J + 1) } #end
      #if (J < NV - 1) triangle { P(I, J), P(I + 1, J + 1), P(I, J + 1) } #end
      #declare I = I + 1;
    #end
    #declare J = J + 1;
  #end
}
KGrid(object { Ball translate y * 0.45 })

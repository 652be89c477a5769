// Kernel benchmark: mesh2, the UV sphere of mesh.pov (radius 0.45, 32 x 16, 992 triangles) with a
// normal per vertex (smooth), declared once and placed 64 times. Vertex 0 is the south pole,
// 1 + (J - 1) * NU + I is ring J (1 .. NV - 1), segment I, and the last is the north pole.
#version 3.7;
#include "kernel_common.inc"
#declare NU = 32;
#declare NV = 16;
#declare NVert = 2 + (NV - 1) * NU;
#macro Dir(I, J) <sin(pi * J / NV) * cos(2 * pi * I / NU), -cos(pi * J / NV), sin(pi * J / NV) * sin(2 * pi * I / NU)> #end
#macro V(I, J) (J = 0 ? 0 : (J = NV ? NVert - 1 : 1 + (J - 1) * NU + mod(I, NU))) #end
#declare Ball = mesh2 {
  vertex_vectors {
    NVert
    <0, -0.45, 0>
    #for (J, 1, NV - 1) #for (I, 0, NU - 1) 0.45 * Dir(I, J) #end #end
    <0, 0.45, 0>
  }
  normal_vectors {
    NVert
    <0, -1, 0>
    #for (J, 1, NV - 1) #for (I, 0, NU - 1) Dir(I, J) #end #end
    <0, 1, 0>
  }
  face_indices {
    NU * (2 * NV - 2)
    #for (J, 0, NV - 1)
      #for (I, 0, NU - 1)
        #if (J > 0) <V(I, J), V(I + 1, J), V(I + 1, J + 1)> #end
        #if (J < NV - 1) <V(I, J), V(I + 1, J + 1), V(I, J + 1)> #end
      #end
    #end
  }
}
KGrid(object { Ball translate y * 0.45 })

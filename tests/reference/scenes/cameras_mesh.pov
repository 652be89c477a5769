// Camera reference: mesh_camera distribution 3 with smooth, a uv-mapped pinhole mesh (as the
// meshcam_pinhole_uv macro of POV-Ray's samples builds one, here without trace()): every image
// point is looked up in the uv map, and the ray leaves the face point with the same barycentric
// coordinates along the interpolated vertex normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare NX = 32;
#declare NY = 24;
#declare Aspect = 4 / 3;
#declare Dist = 1.2;
// A grid vertex: the image-plane point pushed onto the unit sphere; its normal looks outwards.
#macro P(I, J) vnormalize(<(I / NX - 0.5) * Aspect, 0.5 - J / NY, Dist>) #end
#macro UV(I, J) <I / NX, 1 - J / NY> #end
#declare CamMesh = mesh {
  #declare J = 0;
  #while (J < NY)
    #declare I = 0;
    #while (I < NX)
      smooth_triangle { P(I, J), P(I, J), P(I + 1, J), P(I + 1, J), P(I + 1, J + 1), P(I + 1, J + 1)
        uv_vectors UV(I, J), UV(I + 1, J), UV(I + 1, J + 1) }
      smooth_triangle { P(I, J), P(I, J), P(I + 1, J + 1), P(I + 1, J + 1), P(I, J + 1), P(I, J + 1)
        uv_vectors UV(I, J), UV(I + 1, J + 1), UV(I, J + 1) }
      #declare I = I + 1;
    #end
    #declare J = J + 1;
  #end
}

camera {
  mesh_camera { 1 3
    mesh { CamMesh rotate 12 * x rotate -10 * y translate <1, 3, -8> }
    smooth
  }
  location <0, 0, 0>
}

light_source { <4, 10, -6> color rgb 1 }
light_source { <-6, 6, 3> color rgb 0.4 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.15 } }
sphere { <0, 1, 3>, 1 pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <-3, 0.8, 1>, 0.8 pigment { color rgb <0.2, 0.8, 0.3> } }
sphere { <3, 0.7, 0.5>, 0.7 pigment { color rgb <0.9, 0.8, 0.2> } }
box { <1.5, 0, 5>, <3.5, 2.5, 6> pigment { color rgb <0.3, 0.4, 1> } }
box { <-4, 0, -4>, <-2.5, 1.5, -2.5> pigment { color rgb <0.8, 0.3, 0.9> } }
sphere { <4, 1, -4>, 1 pigment { color rgb <0.2, 0.9, 0.9> } }
sphere { <0, 5, 2>, 0.8 pigment { color rgb <1, 0.6, 0.1> } }

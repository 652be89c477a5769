// Camera reference: mesh_camera distribution 0, two rays per pixel from two meshes (the second
// moved a little, for POV-Ray's "fake antialiasing"), each face a pixel: face w·y + x of mesh r is
// ray r of pixel (x, y), shot from the face's centroid along its normal. The meshes have faces for
// the top rows only; the pixels below have no ray and stay black.
#version 3.7;
global_settings { assumed_gamma 1.0 }

#declare NX = 640;
#declare NY = 60;
#declare Px = 4 / 3 / NX;
// An orthographic grid of small upright triangles (top, bottom right, bottom left) facing +z,
// as POV-Ray's meshcam_orthographic macro builds them, the view 6 units wide.
#declare CamMesh = mesh {
  #declare J = 0;
  #while (J < NY)
    #declare I = 0;
    #while (I < NX)
      #declare C = <(I + 0.5) * Px - 2 / 3, 0.5 - (J + 0.5) * Px, 0>;
      triangle { C + <0, Px / 3, 0>, C + <Px / 3, -Px / 6, 0>, C + <-Px / 3, -Px / 6, 0> }
      #declare I = I + 1;
    #end
    #declare J = J + 1;
  #end
}

camera {
  mesh_camera { 2 0
    mesh { CamMesh scale 4.5 rotate 15 * x translate <0, 3, -8> }
    mesh { CamMesh scale 4.5 translate <0.25, -0.25, 0> * 4.5 * Px rotate 15 * x translate <0, 3, -8> }
  }
  location <0, 0, -0.01>
}

light_source { <4, 10, -6> color rgb 1 }
light_source { <-6, 6, 3> color rgb 0.4 }
background { color rgb <0.3, 0.5, 0.8> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.15 } }
sphere { <0, 1, 3>, 1 pigment { color rgb <1, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <-2, 4.6, 2>, 0.8 pigment { color rgb <0.2, 0.8, 0.3> } }
box { <1.5, 0, 5>, <3.5, 4.5, 6> pigment { color rgb <0.3, 0.4, 1> } }
sphere { <0, 5, 2>, 0.8 pigment { color rgb <1, 0.6, 0.1> } }

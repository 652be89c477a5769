// uv_mapping reference: a checker and an image_map through each shape's surface coordinates
// (sphere, torus, mesh with uv_vectors, mesh2 with uv_indices), rotated and scaled so that the
// object's transforms must not move the uv-mapped pigment; `uv_mapping` written on the object,
// on the texture and on the pigment. Lit flatly (ambient 1) so the pattern is what is compared.
#version 3.7;
global_settings { assumed_gamma 1.0 }

camera { location <0, 0.6, -9> look_at <0, 0.2, 0> angle 50 }
background { color rgb <0.3, 0.5, 0.8> }
#declare Flat = finish { ambient 1 diffuse 0 };
#declare Img = "../images/test16.png"
#declare Check = pigment { checker color rgb <1, 0.2, 0.1> color rgb <0.95, 0.95, 0.8> scale 0.125 }

sphere { 0, 1.3 uv_mapping pigment { Check } finish { Flat } rotate <20, 30, 0> translate <-2.7, 1.6, 0> }
sphere { 0, 1.3 texture { uv_mapping pigment { image_map { png Img } } finish { Flat } } rotate <-10, -40, 0> translate <0, 1.6, 0> }
torus { 1, 0.4 texture { pigment { uv_mapping checker color rgb <0.1, 0.7, 0.2> color rgb 1 scale <0.0625, 0.125, 1> } finish { Flat } } rotate <-60, 20, 0> translate <2.8, 1.6, 0> }
torus { 1, 0.4 texture { pigment { uv_mapping image_map { png Img } } finish { Flat } } rotate <-50, -10, 0> scale 1.1 translate <-2.7, -1.4, 0> }
// A bent quad strip: two triangles a face, uv corners given per triangle.
mesh {
  #declare I = 0;
  #while (I < 6)
    #declare A = radians(-60 + I * 20); #declare B = radians(-60 + (I + 1) * 20);
    triangle { <sin(A), -1, -cos(A)>, <sin(B), -1, -cos(B)>, <sin(B), 1, -cos(B)>
      uv_vectors <I / 6, 0>, <(I + 1) / 6, 0>, <(I + 1) / 6, 1> }
    triangle { <sin(A), -1, -cos(A)>, <sin(B), 1, -cos(B)>, <sin(A), 1, -cos(A)>
      uv_vectors <I / 6, 0>, <(I + 1) / 6, 1>, <I / 6, 1> }
    #declare I = I + 1;
  #end
  texture { uv_mapping pigment { image_map { png Img } } finish { Flat } }
  scale 1.2 rotate y * 10 translate <0, -1.4, 0>
}
mesh2 {
  vertex_vectors { 4, <-1, -1, 0>, <1, -1, 0>, <1, 1, 0>, <-1, 1, 0> }
  uv_vectors { 4, <0, 0>, <2, 0>, <2, 2>, <0, 2> }
  face_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_indices { 2, <0, 1, 2>, <0, 2, 3> }
  uv_mapping
  pigment { checker color rgb <0.1, 0.3, 1> color rgb 1 scale 0.25 }
  finish { Flat }
  rotate <10, -30, 20> translate <2.8, -1.4, 0>
}

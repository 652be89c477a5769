// Meshes: a declared pyramid `mesh` (solid by its inside_vector) placed twice and carved by a
// sphere, a smooth `mesh` of smooth_triangles (a sphere made by loops), a `mesh2` wavy sheet
// with normal_vectors/normal_indices, rotated and scaled, and a lone smooth_triangle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "colors.inc"

camera {
    location <0, 4, -9>
    look_at <0, 1, 0>
    angle 55
}

light_source { <4, 9, -6> color White }
light_source { <-7, 4, -2> color rgb 0.4 }

plane { y, 0 pigment { color rgb 0.85 } }

#declare Pyramid = mesh {
    triangle { <-1, 0, -1>, <1, 0, -1>, <0, 1.5, 0> }
    triangle { <1, 0, -1>, <1, 0, 1>, <0, 1.5, 0> }
    triangle { <1, 0, 1>, <-1, 0, 1>, <0, 1.5, 0> }
    triangle { <-1, 0, 1>, <-1, 0, -1>, <0, 1.5, 0> }
    triangle { <-1, 0, -1>, <1, 0, -1>, <1, 0, 1> }
    triangle { <-1, 0, -1>, <1, 0, 1>, <-1, 0, 1> }
    inside_vector y
}
object { Pyramid rotate y*20 translate <-3.2, 0, 1.5> pigment { color rgb <1, 0.35, 0.2> } finish { phong 0.5 } }
difference {
    object { Pyramid scale <0.8, 1.4, 0.8> rotate y*-35 }
    sphere { <0, 1.5, -0.6>, 0.75 }
    translate <3.3, 0, 1.2>
    pigment { color rgb <0.3, 0.85, 0.35> }
}

// A smooth sphere of 12 x 24 quads: smooth_triangles whose normals are the radii.
#declare R = 1.1;
mesh {
    #declare I = 0;
    #while (I < 12)
        #declare J = 0;
        #while (J < 24)
            #declare T0 = pi * I / 12; #declare T1 = pi * (I + 1) / 12;
            #declare P0 = 2 * pi * J / 24; #declare P1 = 2 * pi * (J + 1) / 24;
            #declare A = <sin(T0) * cos(P0), cos(T0), sin(T0) * sin(P0)>;
            #declare B = <sin(T0) * cos(P1), cos(T0), sin(T0) * sin(P1)>;
            #declare C = <sin(T1) * cos(P0), cos(T1), sin(T1) * sin(P0)>;
            #declare D = <sin(T1) * cos(P1), cos(T1), sin(T1) * sin(P1)>;
            #if (I > 0) smooth_triangle { A * R, A, B * R, B, C * R, C } #end
            #if (I < 11) smooth_triangle { B * R, B, D * R, D, C * R, C } #end
            #declare J = J + 1;
        #end
        #declare I = I + 1;
    #end
    translate <-0.6, 1.1, 0.2>
    pigment { color rgb <0.25, 0.55, 1> }
    finish { phong 0.8 phong_size 40 }
}

// A wavy sheet, 8 x 8 quads, with its analytic normals.
#declare N = 8;
mesh2 {
    vertex_vectors { (N + 1) * (N + 1)
        #declare I = 0; #while (I <= N) #declare J = 0; #while (J <= N)
            , <I / N, 0.15 * sin(2 * pi * I / N) * cos(2 * pi * J / N), J / N>
        #declare J = J + 1; #end #declare I = I + 1; #end
    }
    normal_vectors { (N + 1) * (N + 1)
        #declare I = 0; #while (I <= N) #declare J = 0; #while (J <= N)
            , <-0.3 * pi * cos(2 * pi * I / N) * cos(2 * pi * J / N), 1, 0.3 * pi * sin(2 * pi * I / N) * sin(2 * pi * J / N)>
        #declare J = J + 1; #end #declare I = I + 1; #end
    }
    face_indices { 2 * N * N
        #declare I = 0; #while (I < N) #declare J = 0; #while (J < N)
            #declare K = I * (N + 1) + J;
            , <K, K + 1, K + N + 1>, <K + 1, K + N + 2, K + N + 1>
        #declare J = J + 1; #end #declare I = I + 1; #end
    }
    normal_indices { 2 * N * N
        #declare I = 0; #while (I < N) #declare J = 0; #while (J < N)
            #declare K = I * (N + 1) + J;
            , <K, K + 1, K + N + 1>, <K + 1, K + N + 2, K + N + 1>
        #declare J = J + 1; #end #declare I = I + 1; #end
    }
    scale <2.2, 2, 1.6> rotate x*-25 rotate y*15 translate <0.4, 0.4, -2.6>
    pigment { color rgb <1, 0.8, 0.2> }
    finish { specular 0.6 }
}

smooth_triangle {
    <1.4, 2.3, 1>, <-0.5, 0.3, -1>, <2.6, 2.6, 1.5>, <0.5, 0.5, -1>, <1.8, 3.5, 1.2>, <0, 1, -1>
    pigment { color rgb <0.8, 0.4, 0.9> }
}

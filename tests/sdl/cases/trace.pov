// trace(): hit point and normal (into a vector identifier, an array element, a macro's alias), misses, the
// depth limit at a surface, CSG and inverse normals, and inside() of shapes only the renderer tests.
#version 3.7;
#include "shapes.inc"
#macro Show(Name, P, N)
  #debug concat(Name, " ", vstr(3, P, ",", 0, 6), " ", vstr(3, N, ",", 0, 6), "\n")
#end
#declare N = <0, 0, 0>;
#declare S = sphere { <0, 1, 0>, 1 }
#declare P = trace(S, <0, 5, 0>, -y, N); Show("sphere", P, N)
#declare P = trace(S, <3, 5, 0>, -y, N); Show("miss", P, N)
#declare P = trace(S, <0, 0, 0>, -y, N); Show("at surface", P, N)
#declare P = trace(S, <0, 0, 0>, y, N); Show("through", P, N)
#declare D = difference { box { -1, 1 } sphere { <0, 1, 0>, 0.8 } }
#declare P = trace(D, <0.1, 5, 0.2>, -y, N); Show("difference", P, N)
#declare I = sphere { 0, 2 inverse }
#declare P = trace(I, <0.5, 0.2, 0>, <1, 1, 1>, N); Show("inverse", P, N)
#declare T = torus { 2, 0.5 rotate 30*x translate <0.3, 0.2, 0.1> }
#declare P = trace(T, <2.1, 5, 0.3>, <0.1, -1, 0.05>, N); Show("torus", P, N)
#declare Q = <0, 0, 0>;
#declare A = array[2] { <0, 0, 0>, <0, 0, 0> }
#declare P = trace(S, <0.2, 5, 0.1>, -y, A[1]); Show("element", P, A[1])
#if (IsectN(<0, 1, -5>, z, S, Q, N)) Show("IsectN", Q, N) #end
#declare C = cylinder { 0, y, 1 scale <1, 2, 0.5> }
#debug concat("inside ", str(inside(C, <0.1, 1, 0.1>), 0, 0),
              str(inside(C, <0.1, 1, 0.6>), 0, 0), "\n")
camera {}
sphere { 0, 1 }

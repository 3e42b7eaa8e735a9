// Tests min_extent/max_extent of the shapes whose boxes POV-Ray makes in its own ways: a blob (the spheres bounding
// its elements), a lathe, a sor and a prism (their profile's extent), a quadric inside an intersection (recomputed
// within the box), a superellipsoid, a height field from a function (its samples' range), a clipped sphere and a
// union turned twice (its box carried through each rotation). Each object is drawn inside the edges of its box.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -11> look_at <0, 0.9, 0> angle 50 }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 9, -9> color rgb <1, 1, 1> }
plane { y, -0.6 pigment { color rgb <0.7, 0.7, 0.65> } }
#macro Edge(A, B) cylinder { A, B, 0.02 } #end
#macro Framed(O, Colour, Where)
  #local Lo = min_extent(O);
  #local Hi = max_extent(O);
  union {
    object { O pigment { color Colour } }
    union {
      Edge(Lo, <Hi.x, Lo.y, Lo.z>) Edge(<Lo.x, Hi.y, Lo.z>, <Hi.x, Hi.y, Lo.z>)
      Edge(Lo, <Lo.x, Hi.y, Lo.z>) Edge(<Hi.x, Lo.y, Lo.z>, <Hi.x, Hi.y, Lo.z>)
      Edge(<Lo.x, Lo.y, Hi.z>, Hi) Edge(Lo, <Lo.x, Lo.y, Hi.z>) Edge(<Hi.x, Hi.y, Lo.z>, Hi)
      sphere { Hi, 0.05 }
      pigment { color rgb <1, 1, 1> }
    }
    translate Where - (Lo + Hi) / 2 * <1, 0, 1>
  }
#end
#declare Blob1 = blob { threshold 0.5 sphere { 0, 0.8, 1 } cylinder { <-0.5, 0, 0>, <0.5, 0.6, 0>, 0.4, 1 scale <1, 1.5, 1> } }
#declare Lathe1 = lathe { cubic_spline 6, <0, 0>, <0.5, 0.1>, <0.7, 0.5>, <0.25, 0.85>, <0.5, 1.25>, <0, 1.5> }
#declare Sor1 = sor { 5, <0, 0>, <0.5, 0.1>, <0.25, 0.5>, <0.6, 1>, <0, 1.5> }
#declare Prism1 = prism { conic_sweep linear_spline 0.4, 1, 5, <1, 1>, <-1, 1>, <-1, -1>, <1, -1>, <1, 1> rotate 180 * x translate y scale 0.7 }
#declare Quadric1 = intersection { object { Cylinder_Y scale 0.5 } box { <-1, -0.5, -1>, <1, 1, 1> } rotate 30 * z }
#declare Super1 = superellipsoid { <0.3, 0.6> scale 0.6 rotate <20, 30, 0> }
#declare Field1 = height_field { function 20, 20 { 0.5 + 0.4 * sin(6 * x) * cos(5 * y) } translate -0.5 scale <1.4, 1, 1.4> }
#declare Clipped1 = sphere { 0, 0.8 clipped_by { box { <-1, -1, -0.5>, <0.5, 0.4, 1> } } }
#declare Turned1 = union { box { -0.4, 0.4 } sphere { 0.5 * x, 0.3 } rotate 40 * y rotate 30 * x }
Framed(Blob1, rgb <0.9, 0.5, 0.2>, <-3.6, 0, 2.5>)
Framed(Lathe1, rgb <0.3, 0.6, 0.9>, <-1.2, 0, 2.5>)
Framed(Sor1, rgb <0.4, 0.85, 0.4>, <1.2, 0, 2.5>)
Framed(Prism1, rgb <0.85, 0.3, 0.6>, <3.6, 0, 2.5>)
Framed(Quadric1, rgb <0.9, 0.8, 0.3>, <-3.6, 0, -0.5>)
Framed(Super1, rgb <0.5, 0.4, 0.9>, <-1.2, 0, -0.5>)
Framed(Field1, rgb <0.3, 0.8, 0.8>, <1.2, 0, -0.5>)
Framed(Clipped1, rgb <0.9, 0.4, 0.3>, <3.6, 0, -0.5>)
Framed(Turned1, rgb <0.6, 0.9, 0.5>, <0, 0, -3>)

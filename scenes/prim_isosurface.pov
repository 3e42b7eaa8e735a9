// Tests the isosurface: sphere and box containers, a function whose gradient exceeds max_gradient (POV-Ray's
// search then skips roots: the rings on the red sphere), a declared function, an internal one from functions.inc,
// a threshold, an open isosurface, the closed container's cut faces (the yellow wave), max_trace, transforms.
// The open sphere uses accuracy 0.0005: with 0.0001 its shadow rays meet it again between 1e-4 and 1e-3 beyond the
// hit, where POV-Ray's shadow cache decides per thread whether that shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "functions.inc"
camera { location <0, 4, -9> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
isosurface { function { x * x + y * y + z * z - 1 } contained_by { sphere { 0, 1.2 } }
  translate <-3, 1.1, 0.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
isosurface { function { sqrt(x * x + z * z) - 0.6 + 0.15 * sin(y * 8) } contained_by { box { <-1, 0, -1>, <1, 2, 1> } }
  max_gradient 2 translate <0, 0, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
#declare F = function(a, b, c) { a * a * a * a + b * b * b * b + c * c * c * c - 0.8 }
isosurface { function { F(x, y, z) } contained_by { box { -1, 1 } } max_gradient 4
  rotate <20, 30, 0> translate <3, 1, 0.5> pigment { color rgb <0.3, 0.4, 0.9> } finish { phong 0.5 } }
isosurface { function { y - 0.3 * sin(x * 3) * cos(z * 3) } contained_by { box { <-1, -0.5, -1>, <1, 0.5, 1> } }
  max_gradient 2 translate <-1.5, 0.6, -2.3> pigment { color rgb <0.9, 0.8, 0.2> } }
isosurface { function { sqrt(x * x + y * y + z * z) - 0.9 } threshold -0.1 accuracy 0.0005 open
  contained_by { box { -0.9, 0.9 } } translate <1.7, 1, -2.4> pigment { color rgb <0.8, 0.4, 0.8> } }
isosurface { function { f_torus(x, y, z, 0.6, 0.2) } contained_by { box { <-0.85, -0.25, -0.85>, <0.85, 0.25, 0.85> } }
  max_trace 3 rotate x * -50 translate <-4.2, 0.6, -2.5> pigment { color rgb <0.9, 0.6, 0.3> } finish { phong 0.3 } }

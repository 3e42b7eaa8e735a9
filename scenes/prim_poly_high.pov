// Tests polynomial surfaces above order 4, which POV-Ray always solves with Sturm sequences: shapesq.inc's Glob_5
// (order 5) and Twin_Glob (order 6), the order-5 surface of the allobjects sample with `sturm`, a clipped order-6
// Sinsurf, and an order-8 superquadric x⁸ + y⁸ + z⁸ = 1 (a rounded cube), transformed.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"
camera { location <0, 3, -9> look_at <0, 0.4, 0> angle 52 }
background { color rgb <0.15, 0.2, 0.3> }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <8, 4, -6> color rgb <0.3, 0.3, 0.4> }
plane { y, -1.5 pigment { checker color rgb 0.9 color rgb 0.5 } }
object { Glob_5 clipped_by { box { <-1.1, -1, -1>, <0, 1, 1> } } scale 1.2 rotate y * -30 translate <-2.6, 0.2, 0> pigment { color rgb <0.9, 0.4, 0.2> }
         finish { phong 0.6 } }
object { Twin_Glob bounded_by { sphere { 0, 1.2 } } scale 1.1 rotate <0, 20, 10> translate <0.3, 1.8, 1> pigment { color rgb <0.3, 0.8, 0.4> }
         finish { phong 0.4 } }
poly { 5,
  <1, 0, 0, 0,  0, 1, 0, 0,  0, 3, 0, 0,  0, 0, 0, 0,  0.2, 0, 3, 0.7,  0, -1, -0.3, 0,  0, 3, 0.7, 0,
   0, 0, 0, 0,  0, 0, 0, 0,  0, 0, -0.9, 0,  0, 0, 0, 0,  0, 0, 0, 0,  0, 0.4, 0, 0,  0, 0, 0, -0.33>
  sturm
  clipped_by { sphere { 0, 1.3 } }
  rotate <0, -45, 0> translate <2.6, 0.3, 0.5> pigment { color rgb <0.3, 0.5, 0.9> } finish { specular 0.5 } }
object { Sinsurf clipped_by { box { -0.9, 0.9 } } scale <1, 1, 0.2> rotate x * -90 translate <-0.3, -0.7, -2.4>
         pigment { color rgb <0.9, 0.8, 0.3> } finish { phong 0.3 } }
// x⁸ + y⁸ + z⁸ − 1: terms in POV-Ray's order, x⁸ first, y⁸ at 120, z⁸ at 156, the constant last (165 in all).
#declare Coeffs = array[165]
#for (I, 0, 164) #declare Coeffs[I] = 0; #end
#declare Coeffs[0] = 1; #declare Coeffs[120] = 1; #declare Coeffs[156] = 1; #declare Coeffs[164] = -1;
poly { 8, < #for (I, 0, 163) Coeffs[I], #end Coeffs[164] > bounded_by { sphere { 0, 1.5 } }
       scale 0.8 rotate <25, 35, 0> translate <2.2, -0.5, -2.6> pigment { color rgb <0.8, 0.5, 0.8> }
       finish { phong 0.5 phong_size 20 } }

// Tests polynomial surfaces (poly, cubic, quartic): the quartic torus and piriform of shapesq.inc (one solved
// with sturm), a rounded-cube quartic, a transformed poly of order 2 (an ellipsoid), and an unbounded cubic saddle.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
#include "shapesq.inc"
camera { location <0, 3, -9> look_at <0, 0.6, 0> angle 50 }
background { color rgb <0.15, 0.2, 0.3> }
light_source { <-6, 10, -8> color rgb 1 }
light_source { <8, 4, -6> color rgb <0.3, 0.3, 0.4> }
plane { y, -1.2 pigment { checker color rgb 0.9 color rgb 0.5 } }
object { Torus_40_12 sturm scale 1 / 30 rotate x * -50 translate <-2.3, 0.5, 0>
         pigment { color rgb <0.9, 0.4, 0.2> } finish { phong 0.6 } }
object { Piriform rotate z * 90 translate <0.1, 0.6, 0> pigment { color rgb <0.3, 0.8, 0.4> } finish { phong 0.4 } }
// x⁴ + y⁴ + z⁴ − 1 = 0: a rounded cube
quartic { <1, 0, 0, 0, 0, 0, 0, 0, 0, 0,  0, 0, 0, 0, 0, 0, 0, 0, 0, 0,  1, 0, 0, 0, 0, 0, 0, 0, 0, 0,  1, 0, 0, 0, -1>
          scale 0.7 rotate <20, 30, 0> translate <2.4, 0.3, 0> pigment { color rgb <0.3, 0.5, 0.9> } finish { specular 0.5 } }
// x²/1.5² + y²/0.6² + z²/0.8² − 1 = 0, then moved
poly { 2, <1/2.25, 0, 0, 0, 1/0.36, 0, 0, 1/0.64, 0, -1> rotate y * 30 translate <0, -0.5, -2.2>
       pigment { color rgb <0.9, 0.8, 0.3> } }
object { Cubic_Saddle_1 scale 1.5 rotate y * 30 translate <0, 1, 9> pigment { color rgb <0.7, 0.6, 0.8> } }

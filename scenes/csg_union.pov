// CSG union: texture inheritance, a light inside the union moving with it, transforms applied to the union, no_shadow forced onto children
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.5, 0> }
light_source { <5, 8, -6> color rgb 1 }
plane { y, 0 pigment { checker rgb 1 rgb 0.3 } }
#declare Pair = union {
  sphere { <-1, 0.7, 0>, 0.7 }
  box { <0.3, 0, -0.5>, <1.5, 1.2, 0.5> pigment { rgb <0.2, 0.4, 1> } }
  light_source { <0, 3, -2> color rgb 0.3 }
  pigment { rgb <1, 0.3, 0.2> }
  finish { phong 0.6 }
}
object { Pair rotate y*20 translate x*0.3 }
union { sphere { <0,0.3,-2>, 0.3 } sphere { <0.8,0.3,-2>, 0.3 } scale <1,1.5,1> no_shadow }

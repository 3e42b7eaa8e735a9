// Tests inverse: an inverted sphere inside an intersection (a hollow carved from a box), inverse of a whole CSG
// (De Morgan: the inverse of a union intersected with a box leaves the box minus both spheres), and inverse on a
// plain primitive (an inverted plane and an inverted box in a difference).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7.5> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -5> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
intersection {
  box { <-3.4, 0, -0.8>, <-1.8, 1.6, 0.8> }
  sphere { <-2.6, 1.6, -0.8>, 0.9 inverse pigment { rgb <0.2, 0.8, 0.4> } }
  pigment { rgb <0.9, 0.8, 0.6> }
}
intersection {
  box { <-1.1, 0, -0.8>, <1.1, 1.6, 0.8> }
  union {
    sphere { <-0.6, 1.6, -0.8>, 0.6 }
    sphere { <0.6, 1.6, -0.8>, 0.6 }
    inverse
    pigment { rgb <0.9, 0.3, 0.2> }
  }
  pigment { rgb <0.8, 0.85, 0.9> }
}
difference {
  box { <1.8, 0, -0.8>, <3.4, 1.6, 0.8> inverse inverse }
  box { <2.2, 0.4, -1>, <3, 1.2, 0> inverse pigment { rgb <0.3, 0.4, 1> } }
  plane { y, 1.25 inverse }   // not 1.2: the cutter box's top there would be a coincident surface
  pigment { rgb <0.9, 0.9, 0.4> }
}

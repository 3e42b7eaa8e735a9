// Tests nested CSG: the difference of an intersection and a union (with an inner merge), the whole thing
// transformed, and texture inheritance through the levels (untextured children take the nearest parent's texture).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.9, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -5> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
difference {
  intersection {
    box { -1, 1 }
    sphere { 0, 1.4 }
    pigment { rgb <0.85, 0.8, 0.6> }
  }
  union {
    box { <-2, -0.3, -0.3>, <2, 0.3, 0.3> }
    merge {
      sphere { <0, 1, -1>, 0.6 }
      box { <-0.25, -2, -0.25>, <0.25, 2, 0.25> pigment { rgb <0.2, 0.4, 1> } }
    }
    pigment { rgb <0.9, 0.25, 0.2> }
  }
  finish { phong 0.5 }
  scale 1.2
  rotate <15, 35, 0>
  translate <0, 1.4, 0>
}

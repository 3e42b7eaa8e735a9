// Tests CSG merge against union with transparent children: the merge of two rgbt 0.5 spheres has no inner surfaces
// (its shadow and the view through it are attenuated twice where they overlap), the union keeps them (four times).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3.5, -7> look_at <0, 0.9, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <0, 9, -3> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.5 } }
merge {
  sphere { <-2.6, 1, 0>, 1 }
  sphere { <-1.4, 1, 0>, 1 }
  pigment { rgbt <1, 0.4, 0.3, 0.5> }
}
union {
  sphere { <1.4, 1, 0>, 1 }
  sphere { <2.6, 1, 0>, 1 }
  pigment { rgbt <0.3, 0.5, 1, 0.5> }
}

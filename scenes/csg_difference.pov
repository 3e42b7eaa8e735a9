// Tests CSG difference: a box minus a textured sphere and a textured cylinder-like box (the cut faces show the
// cutters' textures), and an untextured cutter inheriting the difference's texture.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -5> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
difference {
  box { <-1.2, 0, -1.2>, <1.2, 2, 1.2> pigment { rgb <0.9, 0.85, 0.7> } }
  sphere { <0, 2, -0.4>, 1.1 pigment { rgb <0.9, 0.2, 0.2> } finish { phong 0.6 } }
  box { <-0.5, 0.4, -2>, <0.5, 1.0, 2> pigment { checker rgb <0.2, 0.4, 1> rgb 1 scale 0.25 } }
  rotate y*25 translate <-1.3, 0, 0.6>
}
difference {
  sphere { <2.2, 1, 0>, 1 }
  box { <2.2, 1, -2>, <4, 3, 0> }
  pigment { rgb <0.3, 0.8, 0.4> }
  finish { specular 0.5 }
}

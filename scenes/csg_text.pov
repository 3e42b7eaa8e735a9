// Tests text inside CSG: letters cut through a box (difference: the cut walls carry the text's texture), the
// intersection of a text with a sphere, an inverted text clipped by a box, and a merge of overlapping glyphs
// (offset vector < 0 makes the characters overlap).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 9, -9> color rgb <1, 1, 1> }
light_source { <5, 3, -6> color rgb <0.35, 0.35, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
difference {
  box { <-3.3, 0.1, -0.3>, <0.2, 1.3, 0.3> pigment { color rgb <0.85, 0.8, 0.7> } }
  text { ttf "timrom.ttf" "CUT" 1, 0 scale 1.1 translate <-3.1, 0.3, -0.5> pigment { color rgb <0.9, 0.2, 0.2> } }
  rotate y * 20
}
intersection {
  text { ttf "cyrvetic.ttf" "Ob" 1.5, 0 scale 1.6 translate <0.6, 0.1, -0.4> }
  sphere { <1.8, 1.0, 0.2>, 1.1 }
  pigment { color rgb <0.3, 0.7, 0.9> } finish { phong 0.5 }
}
intersection {
  box { <-2.8, 1.6, -0.2>, <-0.4, 2.6, 0.2> }
  text { ttf "crystal.ttf" "hole" 2, 0 scale 0.8 translate <-2.6, 1.75, -0.5> inverse }
  pigment { color rgb <0.4, 0.8, 0.3> }
}
merge {
  text { ttf "timrom.ttf" "xxx" 0.3, <-0.3, 0.05, 0> }
  sphere { <0, 0, 0>, 0.2 translate <0.3, 0.2, 0> }
  scale 1.2 rotate y * -30 translate <1.2, 1.9, -1.2>
  pigment { color rgbf <0.9, 0.9, 0.4, 0.6> } finish { phong 0.3 }
}

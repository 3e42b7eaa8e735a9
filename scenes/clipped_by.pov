// Tests clipped_by: a sphere clipped by a plane (an open bowl: its inside is visible), a box clipped by a CSG
// (a sphere minus a box) and rotated after the clip, and clipped_by { bounded_by } sharing the bounding list (the
// top of the right sphere is cut off by its bounding box, which itself is removed as unnecessary).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7.5> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb 1 }
light_source { <5, 4, -5> color rgb 0.35 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.6 } }
sphere {
  <-2.5, 1, 0>, 1
  clipped_by { plane { <0.3, 1, -0.4>, 0.2 translate <-2.5, 1, 0> } }
  pigment { rgb <0.9, 0.4, 0.3> }
  finish { phong 0.4 }
}
box {
  -0.8, 0.8
  clipped_by { difference { sphere { 0, 1.05 } box { <-2, 0.3, -2>, <0.3, 2, 2> } } }
  pigment { rgb <0.3, 0.5, 0.9> }
  rotate <20, 30, 0>
  translate <0, 1, 0>
}
sphere {
  <2.5, 1, 0>, 1
  bounded_by { box { <1.5, 0, -1.2>, <3.5, 1.5, 1.2> } }
  clipped_by { bounded_by }
  pigment { rgb <0.4, 0.9, 0.4> }
}

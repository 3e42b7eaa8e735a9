// Tests POV-Ray's ray culling of a merge placed in the scene by its own bounding box, while its children are not
// culled by theirs: a quadric cylinder clipped by a height field (whose inside goes on below its bottom) inside a
// merge with a small sphere further down shows down to the merge's box, which the sphere stretches, not only within
// the cylinder's own box.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -7> look_at <0, -1, 0> angle 45 }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 9, -9> color rgb <1, 1, 1> }
plane { y, -4 pigment { checker color rgb 0.8 color rgb 0.5 } }
merge {
  object {
    Cylinder_Y
    clipped_by { height_field { function 32, 32 { 0.5 + 0.3 * sin(8 * x) * cos(6 * y) } translate <-0.5, 0, -0.5> scale <6, 1.5, 6> } }
    pigment { color rgb <0.9, 0.5, 0.2> }
  }
  sphere { <2.5, -3, 0>, 0.3 pigment { color rgb 1 } }
}

// Tests POV-Ray's ray culling by a clipped object's own bounding box: a quadric cylinder clipped by a height field
// gets the cylinder's box (radius 1) within the height field's box (POV-Ray's Quadric::Compute_BBox at clipped_by).
// The height field's inside goes on below its bottom, so the clipped cylinder goes on downwards, but POV-Ray tests
// it only for rays that meet its box: below the height field it shows only where a ray reached it through that box,
// which the wider height field's box alone would not cut off.
#version 3.7;
#include "shapes.inc"
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -7> look_at <0, -1, 0> angle 45 }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 9, -9> color rgb <1, 1, 1> }
plane { y, -4 pigment { checker color rgb 0.8 color rgb 0.5 } }
object {
  Cylinder_Y
  clipped_by { height_field { function 32, 32 { 0.5 + 0.3 * sin(8 * x) * cos(6 * y) } translate <-0.5, 0, -0.5> scale <6, 1.5, 6> } }
  pigment { color rgb <0.9, 0.5, 0.2> }
}

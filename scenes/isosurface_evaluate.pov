// Tests the isosurface item `evaluate P0, P1, P2` (the adaptive max_gradient): shapes.inc's Supertorus with
// MaxGradient below 1 (which writes `evaluate 1, 10, 0.1`), a sphere with a steep sine ripple found with
// `evaluate 5, 1.2, 0.95` from a max_gradient that is far too low, and the same ripple with its max_gradient given.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "shapes.inc"
camera { location <0, 3, -7> look_at <0, 0.2, 0> angle 50 }
light_source { <-6, 10, -8> color rgb 1 }
background { color rgb <0.2, 0.25, 0.35> }
object { Supertorus(1.0, 0.35, 0.5, 2.5, 0.001, 0.5) pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 }
         rotate x * -30 translate <-2.2, 0.4, 0> }
isosurface { function { sqrt(x * x + y * y + z * z) - 1 + 0.08 * sin(12 * x) * sin(12 * y) }
  contained_by { sphere { 0, 1.2 } } max_gradient 0.5 evaluate 5, 1.2, 0.95
  pigment { rgb <0.4, 0.8, 0.5> } finish { phong 0.4 } translate <0.2, 0.3, 0.8> }
isosurface { function { sqrt(x * x + y * y + z * z) - 1 + 0.08 * sin(12 * x) * sin(12 * y) }
  contained_by { box { -1.2, 1.2 } } max_gradient 0.2 evaluate 0.5, 2, 0.5 accuracy 0.002
  pigment { rgb <0.5, 0.6, 1> } finish { specular 0.4 } rotate y * 40 scale 0.8 translate <2.4, 0.1, -0.6> }
plane { y, -1.2 pigment { checker rgb 0.8 rgb 0.5 } }

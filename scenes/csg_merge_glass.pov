// Tests merge against union for refracting objects (ior 1.5): a ray crossing the union's inner surfaces meets
// the same interior again (POV-Ray's interior list leaves it there and bends the ray back to ior 1), the merge has
// no inner surfaces, and both cast filtered shadows.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3.5, -7> look_at <0, 0.9, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-2, 9, -4> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.3 scale 0.5 } }
merge {
  sphere { <-2.6, 1, 0>, 1 }
  sphere { <-1.4, 1, 0>, 1 }
  pigment { rgbf <1, 0.8, 0.7, 0.85> }
  finish { phong 0.6 }
  interior { ior 1.5 }
}
union {
  sphere { <1.4, 1, 0>, 1 }
  sphere { <2.6, 1, 0>, 1 }
  pigment { rgbf <0.7, 0.8, 1, 0.85> }
  finish { phong 0.6 }
  interior { ior 1.5 }
}

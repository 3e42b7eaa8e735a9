// Tests refraction with the interior list (pipeline §4 "Transmission/refraction"): a glass sphere containing a
// water sphere (nested: the inner one's ior is relative to the outer one's), two overlapping glass spheres as a
// union (inner surfaces refract) and a hollow-looking air bubble (ior 1) inside glass.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 10 }
camera { location <0, 3, -9> look_at <0, 1, 0> }
background { color rgb <0.6, 0.7, 0.9> }
light_source { <-5, 10, -7> color rgb 1 }
plane { y, 0 pigment { checker color rgb 1 color rgb <0.8, 0.2, 0.1> scale 0.7 } }
sphere { <-2.4, 1.3, 0>, 1.3 pigment { color rgbf <1, 1, 1, 0.95> } finish { phong 0.8 } interior { ior 1.5 } }
sphere { <-2.4, 1.3, 0>, 0.7 pigment { color rgbf <0.8, 0.9, 1, 0.95> } interior { ior 1.33 } }
union {
  sphere { <1.6, 1.1, 0>, 1.1 }
  sphere { <2.6, 1.1, 0.5>, 0.9 }
  pigment { color rgbf <0.9, 1, 0.9, 0.9> }
  interior { ior 1.45 }
}
sphere { <0, 0.6, -2.5>, 0.6 pigment { color rgbt <1, 1, 1, 0.9> } interior { ior 1.6 } }
sphere { <0, 0.6, -2.5>, 0.25 pigment { color rgbt <1, 1, 1, 1> } }

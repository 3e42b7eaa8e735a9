// Fake caustics (interior { caustics C }, POV-Ray's ComputeShadowTexture): light crossing a transparent surface toward
// a light is brightened by 1 + |N·L|^(45·C), N the layer's normal, so glass throws a bright core into its shadow.
// Left: caustics 1 on a smooth glass sphere; middle: caustics 0.5 with a bumpy normal (the perturbed normal decides);
// right: the pre-3.1 `caustics` in finish, which POV-Ray moves into the interior unscaled (with a warning).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
light_source { <-2, 9, -3> color rgb 1 }
plane { y, 0 pigment { color rgb 0.7 } }
sphere { <-2, 1, 0>, 0.9 pigment { color rgbf <1, 1, 1, 0.9> } interior { ior 1.5 caustics 1 } }
sphere { <0, 1, 0>, 0.9 pigment { color rgbf <0.9, 1, 0.9, 0.9> } normal { bumps 0.4 scale 0.2 }
  interior { ior 1.5 caustics 0.5 } }
sphere { <2, 1, 0>, 0.9 pigment { color rgbt <1, 0.9, 0.8, 0.8> } finish { caustics 20 } }

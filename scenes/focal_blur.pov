// Tests focal blur (camera aperture, blur_samples, focal_point) with POV-Ray's default confidence 0.9 and variance
// 1/10000: 20 rays per pixel (the 19-point hexagonal lens grid and one Halton point on the disc), sub-pixel
// positions from POV-Ray's hash, lens points jittered by its lookup, and the confidence test after 7, 13 and 19
// rays with POV-Ray's chi-square thresholds. The green sphere is in focus, the others blur.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 50
  aperture 0.6 blur_samples 20 focal_point <0, 0.8, 0> }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } }
sphere { <-1.5, 0.8, 2>, 0.8 pigment { rgb <0.8, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0, 0.8, 0>, 0.8 pigment { rgb <0.2, 0.7, 0.3> } finish { phong 0.6 } }
sphere { <1.2, 0.5, -2.5>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } finish { phong 0.6 } }

// Tests focal blur's confidence test under antialiasing: blur_samples 5, 37 (at least 5 rays, at most 37 in
// POV-Ray's batches 7, 6, 6, 4, 4, 4, 4, 2), confidence 0.975 and variance 1/255 (chess2's high quality), so
// most pixels stop early on POV-Ray's thresholds (its chdtri, whose odd-degree values are off: reproduced); every
// antialiasing sample is itself blurred. A transformed camera (the lens plane turns with it).
// switches: +A0.3 +R2
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 2, -6> look_at <0, 0.8, 0> angle 50 rotate y * 10
  aperture 0.8 blur_samples 5, 37 confidence 0.975 variance 1/255 focal_point <0, 0.8, 0> }
light_source { <-4, 8, -5> color rgb 1 }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.2 } finish { reflection 0.1 } }
sphere { <-1.5, 0.8, 2>, 0.8 pigment { rgb <0.8, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0, 0.8, 0>, 0.8 pigment { rgb <0.2, 0.7, 0.3> } finish { phong 0.6 reflection 0.2 } }
sphere { <1.2, 0.5, -2.5>, 0.5 pigment { rgb <0.2, 0.3, 0.9> } finish { phong 0.6 } }

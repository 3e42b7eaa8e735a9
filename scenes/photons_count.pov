// photons { count N }: the spacing is derived from POV-Ray's estimate of how many photons a spacing gives (the
// targets' bounding spheres, doubled or tripled for refraction and reflection and collecting targets), and the
// photon pass's own limits (max_trace_level, adc_bailout) replace the scene's.
#version 3.7;
global_settings { assumed_gamma 1 max_trace_level 3
  photons { count 20000 max_trace_level 8 adc_bailout 0.01 } }
camera { location <0, 6, -4> look_at <0, -1, 0.5> angle 50 }
light_source { <-6, 8, 3> color rgb 1 photons { refraction on reflection on } }
plane { y, -1 pigment { color rgb 0.8 } finish { ambient 0 } }
sphere { <0, 0.5, 0>, 1
  pigment { rgbf <1, 0.9, 0.7, 0.95> }
  finish { ambient 0 diffuse 0 reflection 0.1 }
  interior { ior 1.5 }
  photons { target refraction on reflection on }
}

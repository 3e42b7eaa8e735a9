// Tests the prism: linear, quadratic, cubic and Bezier outlines swept straight up (one outline left unclosed, which
// POV-Ray closes), conic sweeps (linear and quadratic outlines, one turned upside down), an open prism with two
// sub-outlines (a hole), and one solved with sturm. One pixel, (212, 44) at the open prism's corner, differs: there
// POV-Ray's shadow-ray cache (trace.cpp: the last fully shadowing object is tested first, with MIN_ISECT_DEPTH
// instead of SHADOW_TOLERANCE) lets the corner shadow itself 0.00095 from the hit, which povtrace does not model.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
prism { linear_sweep linear_spline 0, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <0, 0.3>, <-1, 1>
  rotate y * 20 translate <-3, 0, 0.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
prism { quadratic_spline 0, 1.5, 6, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>
  translate <0, 0, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
prism { cubic_spline 0.2, 1.2, 7, <0, -1>, <1, -0.5>, <0.5, 1>, <-0.5, 1>, <-1, -0.5>, <1, -0.5>, <0.5, 1>
  translate <3, 0, 0.5> pigment { color rgb <0.3, 0.4, 0.9> } finish { phong 0.5 } }
prism { bezier_spline 0, 1, 8, <0, 0>, <1, 0>, <1, 1>, <0, 1>, <0, 1>, <-1, 1>, <-1, 0>, <0, 0>
  sturm translate <-1.5, 0, -2.3> pigment { color rgb <0.9, 0.8, 0.2> } }
prism { conic_sweep linear_spline 0.3, 1, 5, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>
  rotate x * 180 translate <1.7, 1.1, -2.4> pigment { color rgb <0.8, 0.4, 0.8> } }
prism { conic_sweep quadratic_spline 1, 0.4, 6, <0, -1>, <1, 0>, <0, 1>, <-1, 0>, <0, -1>, <1, 0>
  scale <1, 1.5, 1> translate <-4.2, -0.6, -2.5> pigment { color rgb <0.9, 0.6, 0.3> } finish { phong 0.3 } }
prism { linear_spline -0.5, 0.5, 8, <-1, -1>, <1, -1>, <1, 1>, <-1, 1>, <-1, -1>, <-0.5, -0.5>, <0.5, -0.5>,
  <0, 0.5> open
  rotate x * -60 translate <1.5, 2.5, 2.5> pigment { color rgb <0.4, 0.9, 0.9> } }

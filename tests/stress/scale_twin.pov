// One scene at any scale: every length is multiplied by S (declared on the command line, 1 by default). Rendered
// at S = 1e-6 … 1e6 it must give the picture of S = 1 (scale_invariance.cmake). It has what absolute tolerances
// break first: objects resting on a floor (contact shadows), a floor plane to the horizon, a thin shell, glass
// with a fading interior, a mirror, and fog.
#version 3.7;
#ifndef (S) #declare S = 1; #end
global_settings { assumed_gamma 1.0 max_trace_level 6 }
camera { location <0, 2.5, -7> * S look_at <0, 0.8, 0> * S angle 55 }
background { color rgb <0.3, 0.45, 0.7> }
light_source { <-5, 9, -6> * S color rgb 1 }
light_source { <6, 5, -4> * S color rgb 0.3 shadowless }
fog { distance 60 * S color rgb <0.3, 0.45, 0.7> }
plane { y, 0 pigment { checker rgb 0.9 rgb 0.35 } scale S }
sphere { <-1.8, 0.8, 0.4>, 0.8 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } scale S }
box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> rotate y * 30 translate <0.4, 0, 1.8> pigment { rgb <0.3, 0.8, 0.3> } scale S }
sphere { <1.6, 0.7, -0.2>, 0.7
  pigment { rgbf <0.9, 0.95, 1, 0.9> } finish { reflection 0.1 }
  interior { ior 1.5 fade_distance 1 * S fade_power 2 fade_color rgb <0.2, 0.5, 0.9> } scale S }
difference {   // a shell 1e-3 thick
  sphere { <0, 0.35, -1.4>, 0.35 }
  sphere { <0, 0.35, -1.4>, 0.349 }
  plane { y, 0.45 inverse }
  pigment { rgb <0.9, 0.8, 0.2> } scale S }
box { <2.6, 0, 1>, <2.7, 2, 3> pigment { rgb 0.2 } finish { reflection 0.8 } scale S }

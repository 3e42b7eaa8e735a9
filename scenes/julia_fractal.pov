// Tests julia_fractal: quaternion sqr and cube, hypercomplex sqr, sin and pwr, a sliced quaternion, a julia in an
// intersection (every hit, POV-Ray's depth lag) and a transparent one (shadow rays re-marched from each crossing),
// under transforms including a non-uniform scale.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -12> look_at <0, 0, 0> angle 42 right x * 4 / 3 }
light_source { <-20, 30, -40> color rgb 1 }
background { rgb <0.6, 0.7, 0.9> }
plane { z, 3 pigment { checker rgb 0.9 rgb 0.6 } }
julia_fractal { <-0.083, 0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
  pigment { rgb <1, 0.6, 0.3> } finish { phong 0.5 } translate <-3.3, 1.6, 0> }
julia_fractal { <-0.03, 0.5, -0.2, -0.5> quaternion cube max_iteration 8 precision 15
  pigment { rgb <0.4, 0.8, 0.4> } scale 1.3 rotate y * 90 translate <0, 1.6, 0> }
julia_fractal { <-0.745, 0, 0.113, 0.05> hypercomplex sqr max_iteration 9 precision 20
  pigment { rgb <0.5, 0.5, 1> } scale <0.6, 1.2, 0.6> rotate <135, -30, 0> translate <3.3, 1.6, 0> }
julia_fractal { <0.4, 0.3, 0.2, 0.1> hypercomplex sin max_iteration 6 precision 30
  pigment { rgb <1, 0.9, 0.3> } scale 0.8 translate <-3.3, -1.7, 0> }
julia_fractal { <-0.3, 0.2, 0.1, 0> hypercomplex pwr(2, 0.3) max_iteration 8 precision 20
  slice <0, 0.2, 0.1, 1>, 0.1 pigment { rgb <1, 0.4, 0.7> } scale 0.8 translate <-1.1, -1.7, 0> }
intersection {
  julia_fractal { <-0.54, 0.57, 0, -0.37> max_iteration 8 precision 20 cube pigment { rgb <0.5, 0.3, 0.5> } }
  box { <-3, -3, -3>, <3, 3, 0.2> pigment { rgb <0.9, 0.9, 0.6> } }
  rotate <0, 30, 110> scale 0.9 translate <1.1, -1.7, 0> }
julia_fractal { <0.02, -0.02, 0.8, 0> quaternion sqr max_iteration 10 precision 20
  pigment { rgbf <1, 0.5, 0.5, 0.8> } scale 0.8 rotate <40, -30, 120> translate <3.3, -1.7, 0> }

// Tests the lathe: linear, quadratic, cubic and Bezier profiles turned about y, one quadratic profile solved with
// sturm, a profile whose end points lie off the axis (an open tube with a negative first x), and a transformed one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -9> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
lathe { linear_spline 6, <0, 0>, <1, 0>, <1.2, 0.5>, <0.5, 1.2>, <0.8, 2>, <0, 2.2>
  translate <-3, 0, 0.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
lathe { quadratic_spline 6, <0, -0.5>, <0, 0>, <1, 0.3>, <0.4, 1>, <0.9, 1.8>, <0, 2.2> sturm
  translate <0, 0, 0.5> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
lathe { cubic_spline 7, <0, -0.5>, <0, 0>, <1, 0.3>, <0.4, 1>, <0.9, 1.8>, <0, 2.2>, <-0.5, 2.5>
  translate <3, 0, 0.5> pigment { color rgb <0.3, 0.4, 0.9> } finish { phong 0.5 } }
lathe { bezier_spline 8, <0, 0>, <1.5, 0>, <0, 1>, <0.6, 1.2>, <0.6, 1.2>, <1.2, 1.5>, <0.5, 2>, <0, 2>
  translate <-1.5, 0, -2.3> pigment { color rgb <0.9, 0.8, 0.2> } }
lathe { linear_spline 4, <-0.2, 0>, <0.6, 0.2>, <0.7, 0.9>, <0.4, 1.1>
  scale <1, 0.8, 1.4> rotate <-30, 0, 25> translate <1.6, 0.9, -2.4> pigment { color rgb <0.8, 0.4, 0.8> }
  finish { specular 0.4 } }

// Tests a camera inside a refracting object (pipeline §4: a camera ray starts inside the interiors that contain
// the camera): the camera sits in a large glass sphere looking at objects outside it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -4> look_at <0, 1, 2> }
background { color rgb <0.4, 0.5, 0.7> }
light_source { <-4, 9, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb <0.2, 0.3, 0.6> } }
sphere { <0, 1.5, -4>, 2 pigment { color rgbf <1, 1, 1, 0.97> } interior { ior 1.3 } }
sphere { <0.5, 1, 3>, 1 pigment { color rgb <0.9, 0.4, 0.1> } finish { phong 0.7 } }

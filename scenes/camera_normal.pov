// Tests the camera's normal { }: every camera ray bent by the pattern at its screen coordinates (x0, y0, 0), here
// bumps scaled to the image and a wave pattern with a slope_map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> angle 50 normal { bumps 0.04 scale 0.06 } }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { checker rgb 0.9, rgb 0.2 } }
sphere { <-1.2, 1, 0>, 1 pigment { rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <0.4, 0, -0.8>, <2.2, 1.6, 0.8> rotate y*-20 pigment { gradient y color_map { [0 rgb <0, 0.4, 1>] [1 rgb 1] } } }

// Tests the cone: truncated (capped), open, a radius-0 tip, the bigger end written first or second, equal radii
// (a cylinder), and a transformed one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
cone { <-3.2, 0, 0>, 1, <-3.2, 2.5, 0>, 0 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
cone { <-0.8, 2, 0>, 0.3, <-0.8, 0, 0>, 0.9 pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
cone { <1.5, 0.2, -1>, 0.8, <1.5, 2.2, 0>, 0.3 open pigment { color rgb <0.3, 0.5, 0.9> } finish { specular 0.4 } }
cone { <3.5, 0, 1>, 0.5, <3.5, 1.5, 1>, 0.5 pigment { color rgb <0.8, 0.7, 0.3> } }
cone { 0, 0.6, y * 1.5, 0.1 scale <1, 1, 0.5> rotate x * -50 translate <0.2, 0.4, -2.8> pigment { color rgb <0.8, 0.4, 0.8> } }

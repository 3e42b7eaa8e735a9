// Tests the disc: plain, with a hole (an annulus), tilted, seen from behind, and a transformed one.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <5, 3, 6> color rgb <0.4, 0.4, 0.5> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
disc { <-2.5, 1.2, 0>, <0, 0.3, -1>, 1.1 pigment { color rgb <0.9, 0.3, 0.2> } }
disc { <0.3, 1.3, 0.5>, <0.2, 0.5, -1>, 1.2, 0.6 pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
// Normal pointing away from the camera: the back side is seen.
disc { <2.8, 1, 0>, <0.3, 0, 1>, 0.9, 0.2 pigment { color rgb <0.3, 0.4, 0.9> } }
disc { 0, y, 1 scale <1.5, 1, 0.5> rotate <-30, 20, 0> translate <0, 0.3, -2.5> pigment { color rgb <0.9, 0.8, 0.2> } }

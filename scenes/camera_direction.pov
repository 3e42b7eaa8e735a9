// Tests the length of camera direction as the zoom (direction 2.5*z, no angle, no look_at), with explicit up and right.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1, -10> direction <0, 0, 2.5> up <0, 1, 0> right <4/3, 0, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-1.2, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <0.45, 0, -0.55>, <1.85, 1.35, 0.45> pigment { color rgb <0.3, 0.4, 0.9> } }

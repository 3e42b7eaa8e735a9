// Tests the default camera (no camera block): location origin, looking along +z, right 1.33, up 1, direction 1.
#version 3.7;
global_settings { assumed_gamma 1.0 }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 6, -4> color rgb <1, 1, 1> }
plane { y, -1.5 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 0, 5>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <-2.2, 0.8, 6>, 0.7 pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.6 } }
box { <1.5, -1.5, 4>, <2.7, -0.3, 5.2> pigment { color rgb <0.3, 0.4, 0.9> } }

// Tests shadows from three coloured point lights: overlapping shadows leave the sum of the unblocked lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -8> look_at <0, 0.5, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-4, 6, -3> color rgb <0.8, 0.2, 0.2> }
light_source { <4, 6, -3> color rgb <0.2, 0.8, 0.2> }
light_source { <0, 7, 4> color rgb <0.2, 0.2, 0.8> }
plane { y, 0 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.05 diffuse 0.9 } }
sphere { <0, 1.2, 0>, 0.8 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.05 diffuse 0.7 phong 0.5 } }
box { <-2.5, 0, 1>, <-1.7, 2.2, 1.8> pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.05 diffuse 0.7 } }

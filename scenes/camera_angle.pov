// Tests camera angle (horizontal field of view 35 degrees measured on right) together with location/look_at.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2, 3, -9> look_at <0, 0.8, 0> angle 35 }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <-1.8, 0.5, -0.5>, 0.5 pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.6 } }
box { <1.3, 0, -0.5>, <2.3, 1, 0.5> pigment { color rgb <0.3, 0.4, 0.9> } }

// Tests the no_shadow modifier: the left sphere and the box cast no shadow, the right sphere does; all are still lit.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -8> look_at <0, 0.8, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-2, 7, -4> color rgb <1, 1, 1> }
light_source { <5, 4, -2> color rgb <0.4, 0.4, 0.5> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-2, 1, 0>, 1 pigment { color rgb <0.9, 0.4, 0.3> } finish { ambient 0.05 diffuse 0.7 phong 0.5 } no_shadow }
sphere { <1.5, 1, 0>, 1 pigment { color rgb <0.3, 0.5, 0.9> } finish { ambient 0.05 diffuse 0.7 phong 0.5 } }
box { <-0.4, 0, 1.5>, <0.4, 2.5, 2.3> pigment { color rgb <0.9, 0.9, 0.4> } finish { ambient 0.05 diffuse 0.7 } no_shadow }

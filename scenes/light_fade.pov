// Tests light fade_distance/fade_power: quadratic fade on one light, linear fade on another, visible along the floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 6, -10> look_at <0, 0, 1> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-3, 1.5, -2> color rgb <1, 0.8, 0.5> fade_distance 2 fade_power 2 }
light_source { <3, 2, 3> color rgb <0.4, 0.6, 1> fade_distance 3 fade_power 1 }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.02 diffuse 0.8 } }
sphere { <0, 0.7, 0.5>, 0.7 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.02 diffuse 0.7 phong 0.5 } }
sphere { <-4, 0.5, 4>, 0.5 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.02 diffuse 0.7 phong 0.5 } }

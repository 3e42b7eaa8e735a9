// Tests a parallel light with point_at: constant light direction, parallel shadows (also from an occluder far from the light).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -9> look_at <0, 0.5, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-3, 6, -2> color rgb <1, 1, 0.95> parallel point_at <0, 0, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.05 diffuse 0.7 } }
sphere { <-2.5, 1, 0>, 0.8 pigment { color rgb <0.9, 0.3, 0.2> } finish { ambient 0.05 diffuse 0.7 phong 0.6 } }
sphere { <0, 0.6, 1.5>, 0.6 pigment { color rgb <0.2, 0.8, 0.3> } finish { ambient 0.05 diffuse 0.7 phong 0.6 } }
box { <2, 0, -1>, <3, 2, 0> pigment { color rgb <0.3, 0.4, 0.9> } finish { ambient 0.05 diffuse 0.7 } }

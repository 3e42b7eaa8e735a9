// Tests a single coloured point light: no distance attenuation, diffuse plus phong, one hard shadow per object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.6, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <1.5, 4, -1.5> color rgb <1, 0.85, 0.6> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.05 diffuse 0.7 } }
sphere { <-1.8, 0.8, 0.5>, 0.8 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.05 diffuse 0.7 phong 0.8 } }
box { <0.8, 0, 0.5>, <2.2, 1.4, 1.9> pigment { color rgb <0.4, 0.6, 0.9> } finish { ambient 0.05 diffuse 0.7 } }

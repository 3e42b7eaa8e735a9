// Tests shadowless lights: no shadows and no phong/specular highlights from the shadowless light, next to a normal light.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.8, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 6, -5> color rgb <0.8, 0.8, 0.8> }
light_source { <5, 3, -5> color rgb <0.5, 0.4, 0.9> shadowless }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.05 diffuse 0.7 } }
sphere { <-1.5, 1, 0>, 1 pigment { color rgb <0.9, 0.8, 0.7> } finish { ambient 0.05 diffuse 0.6 phong 0.9 phong_size 30 } }
sphere { <1.5, 1, 0.5>, 1 pigment { color rgb <0.9, 0.8, 0.7> } finish { ambient 0.05 diffuse 0.6 specular 0.8 roughness 0.03 } }

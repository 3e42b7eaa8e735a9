// Tests Blinn specular highlights with roughness 0.3, 0.05 (default) and 0.005, and specular 0.4 vs 1.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <4, 6, -7> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.5, 0.6, 0.5> } finish { ambient 0.1 diffuse 0.5 specular 0.6 roughness 0.1 } }
sphere { <-3.3, 1, 0>, 1 pigment { color rgb <0.2, 0.3, 0.8> } finish { ambient 0.1 diffuse 0.6 specular 1 roughness 0.3 } }
sphere { <-1.1, 1, 0>, 1 pigment { color rgb <0.2, 0.3, 0.8> } finish { ambient 0.1 diffuse 0.6 specular 1 } }
sphere { <1.1, 1, 0>, 1 pigment { color rgb <0.2, 0.3, 0.8> } finish { ambient 0.1 diffuse 0.6 specular 1 roughness 0.005 } }
sphere { <3.3, 1, 0>, 1 pigment { color rgb <0.2, 0.3, 0.8> } finish { ambient 0.1 diffuse 0.6 specular 0.4 roughness 0.05 } }

// Tests metallic with Blinn specular: highlights tinted by the pigment (metallic 0, 0.5, 1 and bare metallic keyword).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <3, 5, -8> color rgb <1, 1, 1> }
light_source { <-7, 1.5, -1> color rgb <0.7, 0.7, 0.7> }
plane { y, 0 pigment { color rgb <0.4, 0.4, 0.4> } finish { ambient 0.1 diffuse 0.5 } }
sphere { <-3.3, 1, 0>, 1 pigment { color rgb <0.2, 0.8, 0.4> } finish { ambient 0.1 diffuse 0.4 specular 0.9 roughness 0.02 } }
sphere { <-1.1, 1, 0>, 1 pigment { color rgb <0.2, 0.8, 0.4> } finish { ambient 0.1 diffuse 0.4 specular 0.9 roughness 0.02 metallic 0.5 } }
sphere { <1.1, 1, 0>, 1 pigment { color rgb <0.2, 0.8, 0.4> } finish { ambient 0.1 diffuse 0.4 specular 0.9 roughness 0.02 metallic 1 } }
sphere { <3.3, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.6> } finish { ambient 0.1 diffuse 0.4 specular 0.9 roughness 0.02 metallic } }

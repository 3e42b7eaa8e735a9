// Tests assumed_gamma 2.2: shading is unchanged, the EXR receives the working values decoded as x^2.2.
#version 3.7;
global_settings { assumed_gamma 2.2 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> }
background { color rgb <0.2, 0.3, 0.5> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-1.5, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <1.5, 1, 0.5>, 1 pigment { color rgb <0.3, 0.5, 0.9> } finish { ambient 0.2 diffuse 0.9 specular 0.5 } }

// Tests the sphere primitive: several centres and radii, including one the camera sees partly clipped by the image edge.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0, 1.3, 1>, 1.3 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <-2.2, 0.4, -1>, 0.4 pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.6 } }
sphere { <2.1, 0.25, -1.5>, 0.25 pigment { color rgb <0.3, 0.4, 0.9> } finish { phong 0.6 } }
sphere { <5, 1.5, 2>, 2 pigment { color rgb <0.9, 0.8, 0.3> } finish { phong 0.6 } }
sphere { <-1.2, 2.6, -1.5>, 0.3 pigment { color rgb <0.9, 0.9, 0.9> } finish { phong 0.6 } }

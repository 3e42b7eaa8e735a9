// Tests open cylinders: no caps, so the inside of the tube is seen through its ends and lit on its back face.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <5, 6, 4> color rgb <0.4, 0.4, 0.5> }
plane { y, 0 pigment { checker color rgb <0.8, 0.8, 0.7> color rgb <0.5, 0.5, 0.45> } }
cylinder { <-2, 0, 0>, <-2, 1.5, 0>, 1 open pigment { color rgb <0.9, 0.3, 0.2> } finish { diffuse 0.7 } }
cylinder { <0.5, 0.6, -1>, <3, 1.2, 1.5>, 0.6 open pigment { color rgb <0.2, 0.7, 0.9> } finish { phong 0.4 } }
cylinder { <0, 0, 2>, <0, 2.5, 2>, 0.5 open rotate z * 20 pigment { color rgb <0.8, 0.8, 0.3> } }

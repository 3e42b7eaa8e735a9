// Tests the box primitive, including corners given in unsorted order on every axis, and face normals for shading.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <2, 4, -7> look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -5> color rgb <1, 1, 1> }
light_source { <6, 3, -3> color rgb <0.3, 0.3, 0.4> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
box { <-3, 0, -1>, <-1.5, 1.5, 0.5> pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.5 } }
// Unsorted corners: same as <0.5,0,-1>, <1.5,2.5,0>.
box { <1.5, 2.5, -1>, <0.5, 0, 0> pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.5 } }
box { <3.2, 0.8, 2>, <2, 0, 0.6> pigment { color rgb <0.3, 0.4, 0.9> } finish { specular 0.5 } }

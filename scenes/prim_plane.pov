// Tests planes with non-unit normals: <0,2,0>,0.5 is y = 0.5 (distance along the unit normal), plus a tilted back wall.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 1, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-3, 7, -6> color rgb <1, 1, 1> }
plane { <0, 2, 0>, 0.5 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
plane { <1, 0.5, -3>, -4 pigment { color rgb <0.5, 0.6, 0.9> } finish { ambient 0.1 diffuse 0.7 phong 0.3 } }
sphere { <0, 1.5, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }

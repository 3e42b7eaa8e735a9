// Tests an orthographic camera with explicit right and up: the view rectangle is exactly 10 x 6 world units.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { orthographic location <0, 6, -10> right x*10 up y*6 look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-2, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
sphere { <0.3, 0.6, 2>, 0.6 pigment { color rgb <0.2, 0.8, 0.3> } finish { phong 0.6 } }
box { <1.2, 0, -0.8>, <2.8, 1.6, 0.8> rotate y*30 pigment { color rgb <0.3, 0.4, 0.9> } }

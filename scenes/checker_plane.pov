// Tests the checker pigment on a floor plane (two colours, unit squares; plane offset from integer y).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0.3, 4, -8> look_at <0, 0, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, -0.5 pigment { checker color rgb <0.9, 0.9, 0.85>, color rgb <0.15, 0.2, 0.4> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <0.5, 0.5, 0.5>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }

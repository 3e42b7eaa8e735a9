// Tests phong highlights with phong_size 5, 40 (default) and 150 (exponent >= 60 has a cut-off), and phong 0.4 vs 1.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-4, 6, -7> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.5, 0.5, 0.6> } finish { ambient 0.1 diffuse 0.5 phong 0.5 phong_size 20 } }
sphere { <-3.3, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { ambient 0.1 diffuse 0.6 phong 1 phong_size 5 } }
sphere { <-1.1, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { ambient 0.1 diffuse 0.6 phong 1 } }
sphere { <1.1, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { ambient 0.1 diffuse 0.6 phong 1 phong_size 150 } }
sphere { <3.3, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.2> } finish { ambient 0.1 diffuse 0.6 phong 0.4 phong_size 40 } }

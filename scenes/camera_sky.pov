// Tests camera sky: look_at with sky <1,2,0> rolls the image; the direction of up is ignored under look_at.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> sky <1, 2, 0> up y right x*1.33 look_at <0, 0.8, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.7> } finish { ambient 0.1 diffuse 0.7 } }
sphere { <-1.5, 1, 0>, 1 pigment { color rgb <0.9, 0.3, 0.2> } finish { phong 0.6 } }
box { <0.6, 0, -0.6>, <2.2, 2.5, 0.6> pigment { color rgb <0.3, 0.4, 0.9> } finish { phong 0.4 } }

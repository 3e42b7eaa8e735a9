// Tests negative lights: a light of colour -0.6 takes light away where it reaches (a spotlight ring cut out of a
// brighter one, and a negative point light darkening a sphere's side), as POV-Ray lights them: a light counts
// unless every channel is within EPSILON of 0 (by magnitude).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -7> look_at <0, 0.5, 0> }
light_source { <0, 8, 0> color rgb 1 spotlight point_at <0, 0, 0> radius 25 falloff 30 }
light_source { <0, 8, 0> color rgb -0.6 spotlight point_at <0, 0, 0> radius 10 falloff 14 }
light_source { <-5, 3, -3> color rgb <0.5, 0.4, 0.3> }
light_source { <5, 2, -2> color rgb <-0.3, -0.1, 0> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.6 } }
sphere { <1.5, 1, 0.5>, 1 pigment { color rgb <0.9, 0.6, 0.3> } finish { phong 0.5 } }
box { <-2.5, 0, -0.5>, <-1, 1.5, 1> pigment { color rgb <0.4, 0.7, 0.9> } }

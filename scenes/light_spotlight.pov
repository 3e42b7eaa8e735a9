// Tests spotlights: default cone, radius/falloff smooth edge, tightness, and falloff < radius (hard cut-off).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 9, -9> look_at <0, 0, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-3, 5, 2.5> color rgb <1, 0.9, 0.7> spotlight point_at <-3, 0, 2.5> }
light_source { <3, 5, 2.5> color rgb <0.7, 0.9, 1> spotlight point_at <3, 0, 2.5> radius 10 falloff 25 }
light_source { <-3, 5, -2.5> color rgb <0.9, 1, 0.7> spotlight point_at <-3, 0, -2.5> radius 15 falloff 30 tightness 20 }
light_source { <3, 5, -2.5> color rgb <1, 0.7, 0.9> spotlight point_at <3.5, 0, -2> radius 20 falloff 12 }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.05 diffuse 0.8 } }
sphere { <-3, 0.5, 2.5>, 0.5 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.05 diffuse 0.7 phong 0.7 } }
sphere { <3, 0.5, 2.5>, 0.5 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0.05 diffuse 0.7 phong 0.7 } }

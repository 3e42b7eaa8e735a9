// Tests finish emission alone (ambient 0, diffuse 0): emission is multiplied by the pigment and ignores lights.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.7, 0.7, 0.7> } finish { ambient 0 diffuse 0 emission 0.2 } }
sphere { <-2.4, 1, 0>, 1 pigment { color rgb <1, 0.4, 0.2> } finish { ambient 0 diffuse 0 emission 0.6 } }
sphere { <0, 1, 0.5>, 1 pigment { color rgb <0.3, 0.9, 0.5> } finish { ambient 0 diffuse 0 emission 1.5 } }
sphere { <2.4, 1, 0>, 1 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0 diffuse 0 emission <0.2, 0.5, 0.9> } }

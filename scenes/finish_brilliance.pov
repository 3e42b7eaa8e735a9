// Tests finish brilliance: the diffuse falloff exponent (0.5, 1, 3, 8) on four spheres lit from the side.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 1.5, -8> look_at <0, 1, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-6, 5, -5> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.6, 0.6, 0.6> } finish { ambient 0.05 diffuse 0.6 } }
sphere { <-3.3, 1, 0>, 1 pigment { color rgb <0.9, 0.5, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 0.5 } }
sphere { <-1.1, 1, 0>, 1 pigment { color rgb <0.9, 0.5, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 1 } }
sphere { <1.1, 1, 0>, 1 pigment { color rgb <0.9, 0.5, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 3 } }
sphere { <3.3, 1, 0>, 1 pigment { color rgb <0.9, 0.5, 0.3> } finish { ambient 0.05 diffuse 0.8 brilliance 8 } }

// Tests the default finish (ambient 0.1, diffuse 0.6, no highlights) and the default black pigment of an untextured object.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> }
background { color rgb <0.3, 0.35, 0.45> }
light_source { <-5, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { color rgb <0.8, 0.75, 0.6> } }
sphere { <-2.4, 1, 0>, 1 pigment { color rgb <1, 0.4, 0.2> } }
sphere { <0, 1, 0.5>, 1 texture { pigment { color rgb <0.3, 0.9, 0.5> } finish { } } }
// No texture at all: default pigment is black, so only the silhouette shows.
sphere { <2.4, 1, 0>, 1 }

// Tests background colour: rays that miss every object return it (no light dependence); a small object floats in front.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 0, -6> look_at <0, 0, 0> }
background { color rgb <0.25, 0.5, 0.8> }
light_source { <-4, 6, -6> color rgb <1, 1, 1> }
sphere { <0, 0, 0>, 1.2 pigment { color rgb <0.9, 0.7, 0.2> } finish { phong 0.6 } }
box { <1.8, -1.6, -0.5>, <2.8, -0.6, 0.5> pigment { color rgb <0.8, 0.2, 0.3> } }

// Tests crackle (POV-Ray's random cell points): the default form on a floor, metric 1 with an offset and form on a
// sphere, cells on a box (one random value per unit cube), and a crackle normal.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.6, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { crackle scale 0.8 color_map { [0 rgb <0.1, 0, 0>] [0.1 rgb <0.9, 0.7, 0.4>] [1 rgb 1] } } }
sphere { <-1.2, 1, 0>, 1 pigment { crackle metric 1 offset 0.1 form <1, 0, 0> scale 0.3 } finish { ambient 0.6 } }
box { <0.4, 0, -0.8>, <2.2, 1.6, 0.8> rotate y*-20 pigment { cells scale 0.3 color_map { [0 rgb <0, 0, 1>] [1 rgb <1, 1, 0>] } } }
sphere { <0, 2.2, 1>, 0.6 pigment { rgb 0.9 } normal { crackle 1 metric 3 scale 0.2 } }

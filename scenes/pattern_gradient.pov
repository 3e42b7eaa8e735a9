// Tests the gradient pattern: sawtooth along a direction, negative side wrapped, default black-to-white map.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 5, -7> look_at <0, 0.5, 0> }
background { color rgb <0.1, 0.15, 0.25> }
light_source { <-4, 8, -6> color rgb <1, 1, 1> }
plane { y, 0 pigment { gradient x scale 1.5 } finish { ambient 1 diffuse 0 } }
sphere { <0, 1, 0>, 1 pigment { gradient <1, 1, 0> color_map { [0 rgb <1, 0.2, 0>] [1 rgb <0, 0.3, 1>] } } finish { ambient 1 diffuse 0 } }

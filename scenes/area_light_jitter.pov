// Tests area_light jitter: the area_light scene with the 5×5 light jittered. POV-Ray moves the samples randomly; povtrace
// uses its own deterministic offsets. No reference of its own: tests/regression compares the amount of jitter.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> }
background { color rgb <0.2, 0.25, 0.3> }
light_source { <-2, 6, -2> color rgb 0.8 area_light <3, 0, 0>, <0, 0, 3>, 5, 5 jitter }
light_source { <4, 3, -3> color rgb <0.3, 0.3, 0.4> area_light <1, 0, 0>, <0, 1, 0>, 2, 3 }
plane { y, 0 pigment { color rgb <0.9, 0.85, 0.8> } }
sphere { <-1, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.1> } finish { phong 0.5 } }
box { <0.8, 0, -0.5>, <2, 2.2, 0.7> pigment { color rgb <0.2, 0.5, 0.8> } }

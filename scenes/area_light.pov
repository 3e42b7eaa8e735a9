// Tests area_light soft shadows without jitter (pipeline §3 "area_light"): a 5×5 light with POV-Ray's default
// adaptive level (every sample, trapezoid weights), a 2×3 light (uniform weights), both over objects on a floor.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 4, -7> look_at <0, 0.5, 0> }
background { color rgb <0.2, 0.25, 0.3> }
light_source { <-2, 6, -2> color rgb 0.8 area_light <3, 0, 0>, <0, 0, 3>, 5, 5 }
light_source { <4, 3, -3> color rgb <0.3, 0.3, 0.4> area_light <1, 0, 0>, <0, 1, 0>, 2, 3 }
plane { y, 0 pigment { color rgb <0.9, 0.85, 0.8> } }
sphere { <-1, 1, 0>, 1 pigment { color rgb <0.8, 0.2, 0.1> } finish { phong 0.5 } }
box { <0.8, 0, -0.5>, <2, 2.2, 0.7> pigment { color rgb <0.2, 0.5, 0.8> } }

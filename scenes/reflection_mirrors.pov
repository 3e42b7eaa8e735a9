// Tests the recursion limit with two facing mirrors (pipeline §4 "Recursion limits"): a ray deeper than
// max_trace_level is black, not the background; adc_bailout stops light rays early.
#version 3.7;
global_settings { assumed_gamma 1.0 max_trace_level 7 adc_bailout 0.02 }
camera { location <0, 1.5, -3.5> look_at <0, 1, 3> angle 60 }
background { color rgb <0.9, 0.9, 1> }
light_source { <0, 5, 0> color rgb 1 }
plane { y, 0 pigment { checker color rgb <0.8, 0.7, 0.5> color rgb <0.3, 0.2, 0.1> } }
box { <-3, 0, 4>, <3, 3, 4.1> pigment { color rgb <0.05, 0.05, 0.05> } finish { reflection 0.9 ambient 0.1 } }
box { <-3, 0, -4.1>, <3, 3, -4> pigment { color rgb <0.05, 0.05, 0.05> } finish { reflection 0.9 ambient 0.1 } }
sphere { <0.8, 0.7, 1>, 0.7 pigment { color rgb <0.9, 0.2, 0.1> } finish { phong 0.8 } }

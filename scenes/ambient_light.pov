// Tests global_settings ambient_light (a colour multiplying every ambient term); also parses max_trace_level and adc_bailout.
#version 3.7;
global_settings { assumed_gamma 1.0 ambient_light <0.6, 0.9, 1.8> max_trace_level 3 adc_bailout 0.01 }
camera { location <0, 2, -7> look_at <0, 0.8, 0> }
background { color rgb <0.05, 0.05, 0.1> }
light_source { <-5, 8, -6> color rgb <0.8, 0.8, 0.8> }
plane { y, 0 pigment { color rgb <0.8, 0.8, 0.8> } finish { ambient 0.2 diffuse 0.5 } }
sphere { <-2.4, 1, 0>, 1 pigment { color rgb <1, 0.5, 0.3> } finish { ambient 0.4 diffuse 0.4 } }
sphere { <0, 1, 0.5>, 1 pigment { color rgb <0.5, 0.9, 0.5> } finish { ambient <0.5, 0.2, 0.1> diffuse 0.4 } }
sphere { <2.4, 1, 0>, 1 pigment { color rgb <0.9, 0.9, 0.9> } finish { ambient 0 emission 0.2 diffuse 0.4 } }

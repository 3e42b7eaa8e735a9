// Tests global_settings { number_of_waves 3 }: ripples and waves normals sum over that many wave sources instead of
// 10; and hf_gray_16, which POV-Ray 3.7 ignores with a warning (grey output is a command-line option there).
#version 3.7;
global_settings { assumed_gamma 1.0 number_of_waves 3 hf_gray_16 }
camera { location <0, 3, -5> look_at <0, 0.5, 0> }
light_source { <-4, 8, -5> color rgb 1 }
light_source { <5, 3, -4> color rgb 0.3 }
plane { y, 0 pigment { color rgb 0.8 } normal { ripples 0.8 frequency 3 } }
sphere { <-1.2, 1, 0>, 1 pigment { color rgb <1, 0.5, 0.3> } finish { phong 0.5 } normal { waves 0.6 frequency 4 } }
sphere { <1.2, 1, 0>, 1 pigment { color rgb <0.3, 0.6, 1> } finish { phong 0.5 } normal { ripples 1 frequency 6 scale 0.5 } }

// Tests fog (POV-Ray's ComputeFog): a constant fog with filter and transmit together with a ground fog (fog_type 2,
// fog_offset, fog_alt, a tilted up vector), seen over a long checker floor, through a glass sphere (rays inside a
// non-hollow object get no fog) and in a mirror; one hollow transparent box.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2, -8> look_at <0, 1, 4> }
background { color rgb <0.3, 0.4, 0.7> }
light_source { <-10, 20, -10> color rgb 1 }
fog { distance 40 color rgbft <0.8, 0.8, 0.9, 0.3, 0.1> }
fog { fog_type 2 distance 12 color rgb <0.9, 0.7, 0.5> fog_offset 0.5 fog_alt 0.8 up <0.1, 1, 0> }
plane { y, 0 pigment { checker color rgb 1 color rgb <0.2, 0.3, 0.2> } }
sphere { <-2, 1.2, 2>, 1.2 pigment { color rgbf <1, 1, 1, 0.9> } interior { ior 1.3 } }
box { <0.5, 0, 1>, <2, 2.5, 2.5> pigment { color rgbt <0.9, 0.5, 0.3, 0.7> } hollow }
box { <-6, 0, 14>, <6, 5, 14.2> pigment { color rgb 0.05 } finish { reflection 0.8 } }
sphere { <3, 0.8, 6>, 0.8 pigment { color rgb <0.8, 0.2, 0.2> } }

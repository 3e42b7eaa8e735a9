// Tests antialiasing method 1 with POV-Ray's default jitter (+J, amount 1): POV-Ray's jitter is a fixed lookup of
// the sample position (runtime/jitter.hpp), so the image must match POV-Ray's exactly, as without jitter.
// switches: +A0.3 +R3
// The mirror wall is 4.013 high, not 4: with 4, the reflection of its top edge falls exactly on a row of pixel
// corners, where POV-Ray and povtrace round a tie on the edge differently (not an antialiasing difference).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 3, -8> look_at <0, 1, 0> }
background { color rgb <0.2, 0.3, 0.5> }
light_source { <-5, 10, -6> color rgb 1 }
plane { y, 0 pigment { checker color rgb <0.9, 0.9, 0.9> color rgb <0.2, 0.2, 0.25> } finish { reflection 0.2 } }
sphere { <-2, 1, 0>, 1 pigment { color rgb <0.1, 0.1, 0.1> } finish { reflection 0.8 phong 0.6 } }
sphere { <0.5, 1, 1>, 1 pigment { color rgb <0.8, 0.2, 0.1> } finish { reflection rgb <0.2, 0.6, 0.9> } }
sphere { <2.5, 0.6, -1>, 0.6 pigment { color rgb <0.2, 0.8, 0.3> } finish { specular 0.6 roughness 0.02 } }
box { <-4, 0, 3>, <4, 4.013, 3.2> pigment { color rgb <0.3, 0.3, 0.3> } finish { reflection 0.6 } }

// Tests nested media: a hollow sphere with emitting media inside a hollow box with absorbing and scattering media
// (lit by one light). Inside the sphere a ray is in both interiors, so both media apply there (their coefficients
// add up); between the sphere and the box's walls only the box's media applies.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.2, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-4, 7, -3> color rgb <1, 0.9, 0.8> }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
box { <-2, 0.01, -1.2>, <2, 2.6, 1.2> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { scattering { 1, <0.12, 0.12, 0.15> } absorption <0.25, 0.15, 0.05> } } }
sphere { <0.5, 1.3, -0.1>, 0.9 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { emission <0.2, 0.8, 0.4> } } }

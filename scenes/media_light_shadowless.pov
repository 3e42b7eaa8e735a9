// Tests a shadowless light in scattering media: POV-Ray's media ignore shadowless lights (media.cpp
// ComputeOneMediaLightInterval makes lit intervals for point, spot and cylinder lights only; shadowless is a light
// type of its own), so the orange shadowless light lights the floor and the sphere (without shadows) but is not
// scattered by the box's media; the blue, ordinary light is, with the sphere's shadow volume through the media.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-3, 6, -2> color rgb <1, 0.7, 0.4> shadowless }
light_source { <3, 6, -2> color rgb <0.4, 0.6, 1> }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
sphere { <0, 2.2, -0.3>, 0.4 pigment { color rgb <0.9, 0.9, 0.9> } }
box { <-2, 0.01, -1>, <2, 2.6, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { scattering { 1, 0.12 } } } }

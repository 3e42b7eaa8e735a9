// Tests media_interaction off on a light: a box of scattering media lit by a warm light (default: interacts) and a
// cool light with media_interaction off. Both light the floor and the sphere (with shadows), but only the warm
// light is scattered by the media. Both lights' shadow rays through the box are still dimmed by its media's
// extinction (media inside objects attenuates shadow rays whatever the light's settings, trace.cpp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-4, 7, -3> color rgb <1, 0.8, 0.5> }
light_source { <4, 5, -4> color rgb <0.4, 0.6, 1> media_interaction off }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
sphere { <0.3, 0.6, 2.2>, 0.6 pigment { color rgb <0.9, 0.9, 0.9> } }
box { <-1.8, 0.01, -1>, <1.8, 2.4, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { scattering { 1, 0.15 } } } }

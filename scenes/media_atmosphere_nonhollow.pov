// Tests atmospheric media seen from inside a transparent sphere that is not hollow: the camera is inside it, so
// camera rays start inside a non-hollow object and POV-Ray computes no media along them until they leave it (media
// only along hollow rays). The scene of media_atmosphere_spotlight: the spotlight's beam shows only beyond the
// sphere's surface (radius 8.6 around the camera, cutting the beam). POV-Ray 3.7.0.10 prints no warning: its "Camera is inside a
// non-hollow object. Fog and participating media may not work as expected." is commented out (scene/view.cpp).
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -8> look_at <0, 1.5, 0> }
background { color rgb <0.1, 0.15, 0.3> }
light_source { <0.5, 7, 1> color rgb <1.5, 1.4, 1.1> spotlight point_at <-0.5, 0, 0> radius 14 falloff 20 tightness 2 }
light_source { <-6, 8, -8> color rgb 0.2 media_interaction off }
media { scattering { 1, 0.05 } }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.15 } }
sphere { <0.1, 3.8, 0.6>, 0.6 pigment { color rgb <0.9, 0.3, 0.1> } }
box { <1.8, 0, -1>, <2.8, 1.5, 0> pigment { color rgb <0.2, 0.5, 0.9> } }
sphere { <0, 2.5, -8>, 8.6 pigment { color rgbt <1, 1, 1, 1> } }

// Tests a cylinder light lighting a box of scattering media: only the stretch of a ray inside the light's cylinder
// (radius 0.7, falloff 1) is lit (media.cpp ComputeCylinderLightInterval): a tilted shaft of light through the
// box, with the shadow of a small sphere in it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-2.5, 6, 0> color rgb <1.2, 1.1, 1> cylinder point_at <1, 0, 0> radius 0.7 falloff 1 tightness 2 }
light_source { <5, 8, -6> color rgb 0.2 media_interaction off }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
sphere { <-1.3, 3.6, 0>, 0.3 pigment { color rgb <0.2, 0.9, 0.2> } }
box { <-2.2, 0.01, -1.2>, <2.2, 2.8, 1.2> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { scattering { 1, 0.4 } } } }

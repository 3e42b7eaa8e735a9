// Tests a spotlight lighting a box of scattering media (object media, not atmospheric): the cone is lit with a soft
// edge (radius 10, falloff 20, tightness 5), the stretch of each ray inside the cone is sampled as lit and the rest
// as unlit (media.cpp ComputeSpotLightInterval); the spotlight starts outside the box, above it.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-1, 6, -1> color rgb <1.5, 1.3, 1> spotlight point_at <0.5, 0, 0.3> radius 10 falloff 20 tightness 5 }
light_source { <5, 8, -6> color rgb 0.2 media_interaction off }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
sphere { <-0.1, 2.9, -0.3>, 0.3 pigment { color rgb <0.2, 0.9, 0.2> } }
box { <-2.2, 0.01, -1.2>, <2.2, 2.5, 1.2> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { scattering { 1, 0.2 } absorption 0.05 } } }

// Tests media_attenuation on a light. In POV-Ray 3.7.0.10 it decides only whether the light's shadow rays are
// attenuated by the atmospheric (scene-level) media (trace.cpp ComputeShadowMedia); media inside hollow objects
// attenuates every light's shadow rays, whatever the setting. Here a thin absorbing atmosphere: the left, warm light
// has media_attenuation on, so its light reaching the floor is dimmed (and tinted) by the atmosphere along the way,
// more where the path is longer; the right, cool light (media_attenuation off, the default) reaches the floor
// unattenuated. An absorbing box and an absorbing sphere with a spherical density cast coloured, graded shadows from
// both lights. Camera rays are dimmed by the atmosphere either way.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 7, -6> look_at <0, 0, 0.5> }
light_source { <-5, 5, -1> color rgb <1.2, 1.1, 0.9> media_attenuation on }
light_source { <5, 7, -3> color rgb <0.3, 0.4, 0.6> }
media { absorption <0.04, 0.07, 0.12> }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.5 } }
box { <-2, 0.01, -0.6>, <-0.8, 1.8, 0.6> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { absorption <1.5, 0.3, 0.4> } } }
sphere { <0.6, 1, 0.3>, 0.9 pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { absorption <2.5, 1.5, 0.8> emission <0.3, 0.1, 0> density { spherical scale 0.9 translate <0.6, 1, 0.3> } } } }
sphere { <2.2, 0.4, -1.5>, 0.4 pigment { color rgb <0.8, 0.2, 0.2> } }

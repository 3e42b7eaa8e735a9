// Tests an area light (3×3, not jittered, adaptive 0) lighting a box of scattering media with a small opaque
// sphere in it: the floor gets the area light's soft shadow, but POV-Ray's media samples test the light's shadow as
// from its centre only (trace.cpp TestShadow → TraceShadowRay, no area sampling), so the shadow volume in the media
// is sharp.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.1, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-3, 6, -2> color rgb <1, 0.9, 0.8> area_light <2, 0, 0>, <0, 0, 2>, 3, 3 adaptive 0 }
plane { y, 0 pigment { checker color rgb 0.4 color rgb 0.05 } }
sphere { <-0.8, 2, -0.3>, 0.5 pigment { color rgb <0.9, 0.2, 0.1> } }
box { <-2, 0.01, -1>, <2, 2.6, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior { media { scattering { 1, 0.25 } } } }

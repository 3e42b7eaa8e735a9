// Tests two media in one interior: their emission, absorption and scattering add up (each with its own density):
// a blue emitting media denser at the top (gradient y) plus a media that scatters and absorbs, denser at the
// bottom, lit by one light (with a shadow volume of a small sphere through it). POV-Ray averages the phase function
// over all media of the ray's interiors, scattering or not (media.cpp ComputeMediaScatteringAttenuation, k /=
// medias.size()), so the isotropic scattering here counts half.
#version 3.7;
global_settings { assumed_gamma 1.0 }
camera { location <0, 2.5, -7> look_at <0, 1.2, 0> }
background { color rgb <0.02, 0.02, 0.04> }
light_source { <-4, 7, -3> color rgb <1, 0.9, 0.7> }
plane { y, 0 pigment { checker color rgb 0.6 color rgb 0.1 } }
sphere { <-0.5, 2.2, -0.5>, 0.25 pigment { color rgb <0.9, 0.1, 0.1> } }
box { <-1.5, 0, -1>, <1.5, 2.6, 1> pigment { color rgbt <1, 1, 1, 1> } hollow
  interior {
    media { emission <0.05, 0.15, 0.6> density { gradient y scale 2.6 } }
    media { scattering { 1, <0.5, 0.4, 0.3> } absorption <0, 0.1, 0.3>
            density { gradient y scale 2.6 density_map { [0 color rgb 1] [1 color rgb 0] } } }
  } }

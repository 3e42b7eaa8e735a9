// Tests scattering media of type 3 (Mie murky: a sharp forward lobe, 0.496 (1 + 50 ((1 + cos)/2)^32)), lit from the
// front and from behind (the scene of media_scattering.inc): the light behind the sphere makes a bright spot.
#version 3.7;
#declare ScatteringType = 3;
#include "media_scattering.inc"

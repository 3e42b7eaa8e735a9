// Tests scattering media of type 2 (Mie hazy: a moderate forward lobe, 0.577 (1 + 9 ((1 + cos)/2)^8)), lit from the
// front and from behind (the scene of media_scattering.inc): the light behind the sphere dominates.
#version 3.7;
#declare ScatteringType = 2;
#include "media_scattering.inc"

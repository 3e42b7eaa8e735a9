// Tests scattering { … extinction 0.5 }: isotropic scattering media (the scene of media_scattering.inc) that dims
// what is behind it half as much as the default extinction 1 (media_scattering_isotropic).
#version 3.7;
#declare ScatteringType = 1;
#declare Extinction = 0.5;
#include "media_scattering.inc"

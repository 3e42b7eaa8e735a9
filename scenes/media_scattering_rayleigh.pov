// Tests scattering media of type 4 (Rayleigh: 0.799 (1 + cos²), forward and backward alike, weaker sideways), lit
// from the front and from behind (the scene of media_scattering.inc).
#version 3.7;
#declare ScatteringType = 4;
#include "media_scattering.inc"

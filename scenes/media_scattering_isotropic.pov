// Tests scattering media of type 1 (isotropic: light scattered equally in all directions), lit from the front and
// from behind (the scene of media_scattering.inc).
#version 3.7;
#declare ScatteringType = 1;
#include "media_scattering.inc"

// Tests scattering { … extinction 0 }: isotropic scattering media (the scene of media_scattering.inc) that scatters
// light towards the camera but does not dim what is behind it (the floor and the box, the media itself).
#version 3.7;
#declare ScatteringType = 1;
#declare Extinction = 0;
#include "media_scattering.inc"

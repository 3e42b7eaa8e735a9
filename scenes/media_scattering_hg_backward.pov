// Tests scattering media of type 5 (Henyey-Greenstein) with eccentricity -0.5 (backward scattering: the front light
// dominates), lit from the front and from behind (the scene of media_scattering.inc).
#version 3.7;
#declare ScatteringType = 5;
#declare Eccentricity = -0.5;
#include "media_scattering.inc"

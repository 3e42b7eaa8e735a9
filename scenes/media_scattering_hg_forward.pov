// Tests scattering media of type 5 (Henyey-Greenstein) with eccentricity 0.5 (forward scattering:
// (1 - g²) / (1 + g² - 2 g cos)^1.5), lit from the front and from behind (the scene of media_scattering.inc).
#version 3.7;
#declare ScatteringType = 5;
#declare Eccentricity = 0.5;
#include "media_scattering.inc"

// Tests the noise-based normal perturbations: bumps, dents, wrinkles, ripples and waves, and the pattern normals
// granite, bozo, crackle, marble (with turbulence), agate and spotted, and bumps through a turbulence warp.
#version 3.7;
global_settings { assumed_gamma 1.0 }
#include "noise_tiles.inc"
NormalTile(normal { bumps 0.8 scale 0.1 }, 0, 0)
NormalTile(normal { dents 1 scale 0.2 }, 1, 0)
NormalTile(normal { wrinkles 1 scale 0.2 }, 2, 0)
NormalTile(normal { ripples 1 scale 0.2 }, 3, 0)
NormalTile(normal { waves 1 scale 0.2 }, 0, 1)
NormalTile(normal { granite 0.6 scale 0.5 }, 1, 1)
NormalTile(normal { bozo 1 scale 0.2 }, 2, 1)
NormalTile(normal { crackle 1 scale 0.2 }, 3, 1)
NormalTile(normal { marble 1 turbulence 0.5 scale 0.3 }, 0, 2)
NormalTile(normal { bumps 1 warp { turbulence 0.5 } scale 0.2 }, 1, 2)
NormalTile(normal { agate 1 scale 0.3 }, 2, 2)
NormalTile(normal { spotted 1 scale 0.2 }, 3, 2)

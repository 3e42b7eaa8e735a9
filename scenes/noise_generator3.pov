// Tests the noise-based pigment patterns with noise_generator 3 (Perlin's gradient noise, POV-Ray's SolidNoise): bozo, spotted, granite, marble, wood,
// agate, bumps, dents, wrinkles, turbulence with octaves/omega/lambda, ripples and waves (whose wave sources come
// from the vector noise). POV-Ray's noise is reproduced exactly, so these match its render pixel for pixel.
#version 3.7;
global_settings { assumed_gamma 1.0 noise_generator 3 }
#include "noise_tiles.inc"
NoisePigmentBoard()

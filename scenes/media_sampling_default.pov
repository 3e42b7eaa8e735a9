// Tests media sampling with POV-Ray's defaults (method 3, intervals 1, samples 10, aa_threshold 0.1, aa_level 4,
// jitter 0) on the scene of media_sampling.inc (non-constant density, a spotlight beam, a shadow in the beam): the
// base of the other media sampling scenes.
#version 3.7;
#include "media_sampling.inc"

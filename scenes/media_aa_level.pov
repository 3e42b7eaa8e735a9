// Tests media aa_level 2 (method 3 subdivides a sub-interval at most once: 4 levels by default) with samples 2 on
// the scene of media_sampling.inc; compare media_method3_samples2.
#version 3.7;
#declare SamplesMin = 2;
#declare AALevel = 2;
#include "media_sampling.inc"

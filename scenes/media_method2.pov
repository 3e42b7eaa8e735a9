// Tests media method 2 (regular sampling at the interval's sample centres, (j + 0.5) / samples, no jitter) with
// samples 5 on the scene of media_sampling.inc; compare media_sampling_default (method 3).
#version 3.7;
#declare Method = 2;
#declare SamplesMin = 5;
#include "media_sampling.inc"

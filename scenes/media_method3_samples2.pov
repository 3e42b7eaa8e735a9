// Tests media method 3 with samples 2 (2 / 2 + 1 = 2 sub-intervals per interval, the fewest: samples 1, 2 and 3
// all give 2) on the scene of media_sampling.inc; compare media_sampling_default (samples 10: 6 sub-intervals).
#version 3.7;
#declare Method = 3;
#declare SamplesMin = 2;
#include "media_sampling.inc"

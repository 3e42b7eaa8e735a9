// Tests media method 2 with samples 1,1 (one sample, at the middle of each interval) on the scene of
// media_sampling.inc; compare media_method2 (samples 5).
#version 3.7;
#declare Method = 2;
#declare SamplesMin = 1;
#declare SamplesMax = 1;
#include "media_sampling.inc"

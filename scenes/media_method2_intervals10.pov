// Tests media method 2 with intervals 10 and samples 1 on the scene of media_sampling.inc (the lit and unlit
// stretches of each ray share the 10 intervals by ratio 0.9); compare media_method2_samples1 (intervals 1).
#version 3.7;
#declare Method = 2;
#declare Intervals = 10;
#declare SamplesMin = 1;
#include "media_sampling.inc"

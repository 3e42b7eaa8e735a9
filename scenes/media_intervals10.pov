// Tests media method 3 with intervals 10 (and samples 2, to keep it quick) on the scene of media_sampling.inc: the
// unlit, lit and unlit stretches of each ray share the 10 intervals by ratio 0.9; compare media_method3_samples2
// (intervals 1: one interval per stretch).
#version 3.7;
#declare Intervals = 10;
#declare SamplesMin = 2;
#include "media_sampling.inc"

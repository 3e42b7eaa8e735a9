// Tests media aa_threshold 1 (method 3 subdivides a sub-interval when its end samples differ by more than this: 0.1
// by default, here only the sharpest changes, at the beam's and the shadow's edges, are subdivided) with samples 2
// on the scene of media_sampling.inc; compare media_method3_samples2.
#version 3.7;
#declare SamplesMin = 2;
#declare AAThreshold = 1;
#include "media_sampling.inc"

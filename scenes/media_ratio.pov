// Tests media ratio 0.2 (most of the intervals go to the unlit stretches of a ray instead of the lit ones: 0.9 by
// default) with method 3, intervals 10 and samples 2 on the scene of media_sampling.inc; compare media_intervals10.
#version 3.7;
#declare Intervals = 10;
#declare SamplesMin = 2;
#declare Ratio = 0.2;
#include "media_sampling.inc"

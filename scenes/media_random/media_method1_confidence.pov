// Tests media confidence and variance: method 1 with samples 3,9 as in media_method1_samples3_9 but confidence 0.99
// and variance 1/100000 (a far lower threshold, variance × chdtri(n, confidence), for the samples' variance: more
// extra samples where the media is lit unevenly; POV-Ray's statistics: 3.39 samples per interval against 3.11 with
// the defaults 0.9 and 1/128) on the scene of ../media_sampling.inc. Random in POV-Ray with more than one thread.
#version 3.7;
#declare Method = 1;
#declare SamplesMin = 3;
#declare SamplesMax = 9;
#declare Confidence = 0.99;
#declare Variance = 1/100000;
#include "../media_sampling.inc"

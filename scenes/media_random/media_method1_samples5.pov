// Tests media method 1 with samples 5,5 (five random samples per interval) on the scene of ../media_sampling.inc;
// compare media_method1_samples1. Random in POV-Ray with more than one thread (reference/media_random/).
#version 3.7;
#declare Method = 1;
#declare SamplesMin = 5;
#declare SamplesMax = 5;
#include "../media_sampling.inc"

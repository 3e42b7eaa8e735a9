// Tests media method 2 with jitter 1 (each of the 5 samples moved randomly within its fifth of the interval) on the
// scene of ../media_sampling.inc; compare media_method2 (jitter 0). Random in POV-Ray with more than one thread.
#version 3.7;
#declare Method = 2;
#declare SamplesMin = 5;
#declare Jitter = 1;
#include "../media_sampling.inc"

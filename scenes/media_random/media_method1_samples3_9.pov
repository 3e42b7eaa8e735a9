// Tests media method 1 with samples 3,9: three random samples per interval, then more (up to 9) while the
// samples' variance exceeds variance × chdtri(n, confidence) (defaults: confidence 0.9, variance 1/128) on the scene
// of ../media_sampling.inc; compare media_method1_samples5. Random in POV-Ray with more than one thread.
#version 3.7;
#declare Method = 1;
#declare SamplesMin = 3;
#declare SamplesMax = 9;
#include "../media_sampling.inc"

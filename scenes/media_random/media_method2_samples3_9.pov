// Tests media method 2 with samples 3,9: three regularly placed samples per interval, then more (up to 9) at random
// places while the samples' variance exceeds the threshold (media.cpp ComputeMediaRegularSampling takes the extra
// samples like method 1) on the scene of ../media_sampling.inc; compare media_method2 (samples 5). Random in POV-Ray
// with more than one thread.
#version 3.7;
#declare Method = 2;
#declare SamplesMin = 3;
#declare SamplesMax = 9;
#include "../media_sampling.inc"

// Tests media method 3 with jitter 0.5 (each adaptive sample moved randomly by up to ± a quarter of its spacing) on
// the scene of ../media_sampling.inc; compare media_sampling_default (jitter 0). Random in POV-Ray with more than one
// thread.
#version 3.7;
#declare Jitter = 0.5;
#include "../media_sampling.inc"

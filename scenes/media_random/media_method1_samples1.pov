// Tests media method 1 (Monte Carlo: each sample at a random place in its interval, POV-Ray's per-thread random
// sequence) with samples 1,1 on the scene of ../media_sampling.inc (rendered from this folder). Random in POV-Ray
// with more than one thread: reproducible with +WT1 only (reference/media_random/).
#version 3.7;
#declare Method = 1;
#declare SamplesMin = 1;
#declare SamplesMax = 1;
#include "../media_sampling.inc"

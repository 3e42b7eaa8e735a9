// POV-Ray's internal functions built on its noise (fnintern.cpp: f_hetero_mf, f_ridge, f_ridged_mf, f_noise3d,
// f_noise_generator), evaluated with povtrace's exact copy of that noise (runtime/noise.hpp). `p` holds x, y, z and
// then the function's parameters, as for every internal function.
#pragma once

namespace povtrace::sdl {

double hetero_mf(const double* p);
double ridge(const double* p);
double ridged_mf(const double* p);
double noise3d(const double* p, int scene_noise_generator);
double noise_with_generator(const double* p);

}  // namespace povtrace::sdl

// See function_noise.hpp. Each follows the order of operations of POV-Ray 3.7's fnintern.cpp so that values agree
// to the last bit.
#include "runtime/function_noise.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "runtime/noise.hpp"

namespace povtrace::sdl {

namespace {
// POV-Ray takes a generator parameter as (int)value & 3: 2 and 3 are the range-corrected and Perlin noise, 0 and 1
// (and anything else) the original one.
NoiseGenerator generator_parameter(double value) {
  if (!(std::fabs(value) < 2147483647.0)) return NoiseGenerator::original;
  switch (static_cast<int>(value) & 3) {
    case 2: return NoiseGenerator::range_corrected;
    case 3: return NoiseGenerator::perlin;
    default: return NoiseGenerator::original;
  }
}


// Loop counts come from scene values; POV-Ray would run them as written. Past this many octaves every further
// term is far below double precision (the point has been scaled beyond the lattice's range), so stopping there
// keeps every evaluation finite in time without changing a value a scene can see.
constexpr double kMaxOctaves = 1024;
int loop_count(double v) { return static_cast<int>(std::clamp(v, -1.0, kMaxOctaves)); }

Vec3 point(const double* p) { return {p[0], p[1], p[2]}; }
double signed_noise(Vec3 v, NoiseGenerator g) { return noise(v, g) * 2.0 - 1.0; }
}  // namespace

// f_hetero_mf(x, y, z, H, lacunarity, octaves, offset, T, generator): Musgrave's heterogeneous multifractal.
double hetero_mf(const double* p) {
  const double h = p[3], lacunarity = p[4], octaves = p[5], offset = p[6], t = p[7];
  const NoiseGenerator g = generator_parameter(p[8]);
  Vec3 v = point(p);
  double signal = signed_noise(v, g) + offset;
  v = v * lacunarity;
  const double step = std::pow(lacunarity, -h);
  double weight = step;
  const int whole = loop_count(std::ceil(octaves));
  for (int i = 1; i < whole && i < octaves; ++i) {
    double increment = (signed_noise(v, g) + offset) * weight;
    for (int k = loop_count(t); k > 0; --k) increment *= signal;   // T = 0: 1/f noise; 1: heterogeneous
    signal += increment;
    v = v * lacunarity;
    weight *= step;
  }
  const double fraction = octaves - static_cast<double>(static_cast<long long>(std::clamp(octaves, -1e18, 1e18)));
  if (fraction != 0.0) {   // the fractional octave
    const double increment = (signed_noise(v, g) + offset) * weight;
    signal += fraction * increment * signal;
  }
  return signal;
}

// f_ridge(x, y, z, lambda, octaves, omega, offset, ridge, generator): turbulence of |noise − ridge|, normalised.
double ridge(const double* p) {
  const double lambda = p[3], octaves_value = p[4], omega = p[5], offset = p[6], ridge_value = p[7];
  const NoiseGenerator g = generator_parameter(p[8]);
  const Vec3 e = point(p);
  const int octaves = loop_count(octaves_value);
  const double rscale = 1.0 / std::max(ridge_value, 1.0 - ridge_value);
  const double scale = 1.0 / std::max(offset, 1.0 - offset);
  const double residue = octaves_value - static_cast<double>(octaves);
  double l = lambda, o = omega, total = 1.0;
  double value = std::fabs(noise(e, g) - ridge_value) * rscale - offset;
  for (int i = 2; i <= octaves; ++i) {
    const double v = std::fabs(noise(e * l, g) - ridge_value) * rscale;
    value += o * (v - offset);
    total += o;
    l *= lambda;
    o *= omega;
  }
  if (residue != 0.0) {
    const double v = std::fabs(noise(e * l, g) - ridge_value) * rscale;
    value += o * (v - offset) * residue;
    total += o * residue;
  }
  return value * scale / total;
}

// f_ridged_mf(x, y, z, H, lacunarity, octaves, offset, gain, generator): Musgrave's ridged multifractal. POV-Ray
// computes the octave weights lacunarity^(−H·i) once, at the first call of the function anywhere in the scene, and
// reuses them for every later call; povtrace computes them from each call's own parameters, which is the same
// whenever a scene calls it with one set of H, lacunarity and octaves (POV-Ray's choice among several sets depends
// on which call its threads happen to run first).
double ridged_mf(const double* p) {
  const double h = p[3], lacunarity = p[4], octaves = p[5], offset = p[6], gain = p[7];
  const NoiseGenerator g = generator_parameter(p[8]);
  Vec3 v = point(p);
  auto ridged = [&](Vec3 q) {
    const double s = offset - std::fabs(signed_noise(q, g));
    return s * s;
  };
  double signal = ridged(v), result = signal, frequency = lacunarity;
  const int count = loop_count(std::ceil(octaves));
  for (int i = 1; i < count && i < octaves; ++i) {
    v = v * lacunarity;
    const double weight = std::clamp(signal * gain, 0.0, 1.0);
    signal = ridged(v) * weight;
    result += signal * std::pow(frequency, -h);
    frequency *= lacunarity;
  }
  return result;
}

// f_noise3d(x, y, z): the scene's noise generator.
double noise3d(const double* p, int scene_noise_generator) {
  return noise(point(p), static_cast<NoiseGenerator>(scene_noise_generator));   // the parser keeps it in 1…3
}

// f_noise_generator(x, y, z, generator).
double noise_with_generator(const double* p) { return noise(point(p), generator_parameter(p[3])); }

}  // namespace povtrace::sdl

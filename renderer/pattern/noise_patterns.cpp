// The noise-based patterns (POV-Ray 3.7 pattern.cpp): granite, marble, wood, agate, dents, wrinkles, and the
// wave-source patterns ripples and waves. bozo, spotted and bumps are the noise itself.
#include <algorithm>
#include <cmath>

#include "renderer/pattern/normal_perturbation.hpp"
#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render::patterns {

// Six octaves of |noise − ½|-shaped ridges at 4× the point's frequency, each halving in weight.
double granite(Vec3 p, NoiseGenerator generator) {
  constexpr int kOctaves = 6;
  const Vec3 base = p * 4.0;
  double value = 0.0, frequency = 1.0;
  for (int i = 0; i < kOctaves; ++i, frequency *= 2.0) {
    const double n = noise(base * frequency, generator);
    // Generator 1 uses |½ − n|; the others |1 − 2n| capped at ½.
    const double ridge = generator == NoiseGenerator::original ? std::fabs(0.5 - n)
                                                               : std::min(std::fabs(1.0 - 2.0 * n), 0.5);
    value += ridge / frequency;
  }
  return value;
}

// x plus the turbulence's x amount times the scalar turbulence; the default triangle wave makes the veins.
double marble(Vec3 p, const std::optional<Turbulence>& turbulence, NoiseGenerator generator) {
  if (!turbulence) return p.x;
  return p.x + turbulence->amount.x * povtrace::turbulence(p, *turbulence, generator);
}

// The spirals (POV-Ray's spiral1_pattern, spiral2_pattern): around the z axis, the angle measured with asin from
// −y through +x (π/2 + asin(y/r), or 3π/2 − asin(y/r) for x < 0). The classic turbulence, which also warps the point
// as for other patterns, is added once more inside, scaled by its x amount.
namespace {
double spiral_angle(double x, double y, double radius) {
  if (radius == 0.0) return 0.0;
  return x < 0.0 ? 3.0 * (M_PI / 2) - std::asin(y / radius) : M_PI / 2 + std::asin(y / radius);
}
double inner_turbulence(Vec3 p, const std::optional<Turbulence>& turbulence, NoiseGenerator generator) {
  return turbulence ? turbulence->amount.x * povtrace::turbulence(p, *turbulence, generator) : 0.0;
}
}  // namespace

double spiral1(Vec3 p, int arms, const std::optional<Turbulence>& turbulence, NoiseGenerator generator) {
  const double turb = inner_turbulence(p, turbulence, generator);
  const double radius = std::sqrt(p.x * p.x + p.y * p.y);
  return p.z + radius + static_cast<double>(arms) * spiral_angle(p.x, p.y, radius) / (2.0 * M_PI) + turb;
}

double spiral2(Vec3 p, int arms, const std::optional<Turbulence>& turbulence, NoiseGenerator generator) {
  const double turb = inner_turbulence(p, turbulence, generator);
  const double radius = std::sqrt(p.x * p.x + p.y * p.y);
  const double along =
      triangle_wave(p.z + radius + static_cast<double>(arms) * spiral_angle(p.x, p.y, radius) / (2.0 * M_PI) + turb);
  return triangle_wave(radius) + along;
}

// Rings around the z axis: the distance from it, with x and y each pushed by a sine of the turbulence-displaced
// coordinate when there is turbulence (z is not used).
double wood(Vec3 p, const std::optional<Turbulence>& turbulence) {
  double x = p.x, y = p.y;
  if (turbulence) {
    const Vec3 t = vector_turbulence(p, *turbulence);
    x += cycloidal((p.x + t.x) * turbulence->amount.x);
    y += cycloidal((p.y + t.y) * turbulence->amount.y);
  }
  return std::sqrt(x * x + y * y);
}

// Layers along z bent by turbulence: ½(sin(2π(1.3·agate_turb·turbulence + 1.1·z)) + 1), raised to the 0.77th power.
double agate(Vec3 p, const Turbulence& turbulence, double agate_turb, NoiseGenerator generator) {
  const double turb = agate_turb * povtrace::turbulence(p, turbulence, generator);
  const double v = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
  if (v < 0.0) return 0.0;
  return std::pow(std::min(1.0, v), 0.77);
}

// dents: the noise cubed (POV-Ray's dents_pattern).
double dents(Vec3 p, NoiseGenerator generator) {
  const double n = noise(p, generator);
  return n * n * n;
}

// wrinkles: ten octaves of noise, each at twice the frequency and half the weight, halved; with the range-corrected
// generators each octave is 2n − ½ clamped to [0, 1] (POV-Ray's wrinkles_pattern).
double wrinkles(Vec3 p, NoiseGenerator generator) {
  auto octave = [&](Vec3 q) {
    const double n = noise(q, generator);
    return generator == NoiseGenerator::original ? n : std::clamp(n * 2.0 - 0.5, 0.0, 1.0);
  };
  double value = octave(p), lambda = 2.0, omega = 0.5;
  for (int i = 1; i < 10; ++i, lambda *= 2.0, omega *= 0.5) value += omega * octave(p * lambda);
  return value / 2.0;
}

namespace {
const std::vector<WaveSource>& wave_sources() {
  static const std::vector<WaveSource> sources = make_wave_sources(10);   // POV-Ray's default number_of_waves
  return sources;
}
// The distance to a wave source; POV-Ray takes 1 at the source itself.
double distance_to(Vec3 p, const WaveSource& s) {
  const double d = length(p - s.centre);
  return d == 0.0 ? 1.0 : d;
}
}  // namespace

// ripples: the mean of the sines of the distances to the wave sources, mapped to [0, 1].
double ripples(Vec3 p, double frequency, double phase) {
  double sum = 0.0;
  for (const WaveSource& s : wave_sources()) sum += cycloidal(distance_to(p, s) * frequency + phase);
  return 0.5 * (1.0 + sum / static_cast<double>(wave_sources().size()));
}

// waves: as ripples, each source at its own frequency and weighted by its inverse.
double waves(Vec3 p, double frequency, double phase) {
  double sum = 0.0;
  for (const WaveSource& s : wave_sources())
    sum += cycloidal(distance_to(p, s) * frequency * s.frequency + phase) / s.frequency;
  return 0.2 * (2.5 + sum / static_cast<double>(wave_sources().size()));
}

}  // namespace povtrace::render::patterns


// The noise-based patterns (POV-Ray 3.7 pattern.cpp): granite, marble, wood and agate. bozo and spotted are the
// noise itself.
#include <algorithm>
#include <cmath>

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
  return p.x + turbulence->amount.x * render::turbulence(p, *turbulence, generator);
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
  const double turb = agate_turb * render::turbulence(p, turbulence, generator);
  const double v = 0.5 * (cycloidal(1.3 * turb + 1.1 * p.z) + 1.0);
  if (v < 0.0) return 0.0;
  return std::pow(std::min(1.0, v), 0.77);
}

}  // namespace povtrace::render::patterns

// See noise.hpp. The lattice, the hashing of lattice points and the S-curve blend follow POV-Ray 3.7's Noise()
// (texture.cpp); the random coefficients at the lattice points are povtrace's own (splitmix64 below), not
// POV-Ray's table.
#include "renderer/pattern/noise.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace povtrace::render {

namespace {
// Lattice coordinates are offset by POV-Ray's MINX (−10000) and wrapped to 12 bits before hashing.
constexpr long long kLatticeOrigin = -10000;
constexpr long long kLatticeMask = 0xFFF;
constexpr int kPermutationSize = 4096;

// POV-Ray's lattice permutation (InitTextureTable): the identity on 0..4095 shuffled from the top down with the
// 32-bit linear congruential generator x ← 1812433253·x + 12345 (bits 16..30 of x, modulo 4096, pick the element
// swapped with position i), then repeated once so two-level lookups never need a modulo.
constexpr std::array<std::uint16_t, 2 * kPermutationSize> make_permutation() {
  std::array<std::uint16_t, 2 * kPermutationSize> p{};
  for (int i = 0; i < kPermutationSize; ++i) p[static_cast<std::size_t>(i)] = static_cast<std::uint16_t>(i);
  std::uint32_t state = 0;
  for (int i = kPermutationSize - 1; i >= 0; --i) {
    state = state * 1812433253u + 12345u;
    const auto j = static_cast<std::size_t>(((state >> 16) & 0x7FFFu) % kPermutationSize);
    const auto k = static_cast<std::size_t>(i);
    const std::uint16_t swap = p[k];
    p[k] = p[j];
    p[j] = swap;
  }
  for (std::size_t i = 0; i < kPermutationSize; ++i) p[i + kPermutationSize] = p[i];
  return p;
}
constexpr auto kPermutation = make_permutation();

// A lattice corner's contribution: a constant in [−0.5, 0.5] plus a ramp with gradient components in [−1, 1],
// the same ranges as POV-Ray's coefficients. 256 of them are reachable from the hash (its low 8 bits); vector
// noise takes its y and z components 4 and 8 entries further on, as DNoise does.
struct Wavelet {
  double constant = 0;
  Vec3 gradient;
};
constexpr int kWavelets = 256;
constexpr int kComponentStride = 4;

// splitmix64 (Steele, Lea, Flood 2014): a fixed, well-mixed stream for the coefficients.
constexpr std::uint64_t splitmix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}
constexpr double symmetric_unit(std::uint64_t& state) {   // uniform in [−1, 1)
  return static_cast<double>(splitmix64(state) >> 11) * 0x1p-52 - 1.0;
}
constexpr std::array<Wavelet, kWavelets + 2 * kComponentStride> make_wavelets() {
  std::array<Wavelet, kWavelets + 2 * kComponentStride> w{};
  std::uint64_t state = 0x706F767472616365ull;   // "povtrace"
  for (auto& e : w) {
    e.constant = 0.5 * symmetric_unit(state);
    e.gradient = {symmetric_unit(state), symmetric_unit(state), symmetric_unit(state)};
  }
  return w;
}
constexpr auto kWaveletTable = make_wavelets();

// POV-Ray's S-curve 3t² − 2t³: the blend weight is smooth across lattice cells.
double s_curve(double t) { return t * t * (3.0 - 2.0 * t); }

// The lattice cell holding one coordinate: its hashed index and the offset inside it. POV-Ray rounds negative
// coordinates down with (int)(x − (1 − EPSILON)), so points within 1e-10 above a negative integer stay in the
// cell below it; this keeps that.
struct CellCoordinate {
  long long index = 0;
  double offset = 0;
};
CellCoordinate cell_of(double x) {
  constexpr double kLimit = 1e15;   // keeps the integer conversion defined far beyond any scene's size
  const double clamped = std::clamp(x, -kLimit, kLimit);
  const double cell = clamped >= 0 ? std::trunc(clamped) : std::trunc(clamped - (1.0 - 1e-10));
  return {(static_cast<long long>(cell) - kLatticeOrigin) & kLatticeMask, clamped - cell};
}

std::size_t hash(std::size_t a, long long b) {
  return kPermutation[kPermutation[a] ^ static_cast<std::size_t>(b)];
}
std::size_t wavelet_index(std::size_t xy_hash, long long z) {
  return kPermutation[xy_hash ^ static_cast<std::size_t>(z)] & 0xFFu;
}

// Sums the 8 corner wavelets around p; `component` picks the coefficient set (0 for scalar noise).
double lattice_sum(Vec3 p, int component) {
  const CellCoordinate cx = cell_of(p.x), cy = cell_of(p.y), cz = cell_of(p.z);
  const double wx[2] = {1.0 - s_curve(cx.offset), s_curve(cx.offset)};
  const double wy[2] = {1.0 - s_curve(cy.offset), s_curve(cy.offset)};
  const double wz[2] = {1.0 - s_curve(cz.offset), s_curve(cz.offset)};
  double sum = 0.0;
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const std::size_t xy = hash(static_cast<std::size_t>(cx.index + i), cy.index + j);
      for (int k = 0; k < 2; ++k) {
        const Wavelet& w = kWaveletTable[wavelet_index(xy, cz.index + k) +
                                         static_cast<std::size_t>(component * kComponentStride)];
        const Vec3 d{cx.offset - i, cy.offset - j, cz.offset - k};
        sum += wx[i] * wy[j] * wz[k] * (w.constant + dot(w.gradient, d));
      }
    }
  return sum;
}

// Generator 2 stretches the raw sum by POV-Ray's factor 0.48985582 (which maps its raw range of about ±1 onto
// [0, 1]); povtrace's coefficients are symmetric, so the centre is 0.5 instead of POV-Ray's empirical offset.
constexpr double kRangeCorrectedScale = 0.48985582;
}  // namespace

std::size_t lattice_hash3(long long x, long long y, long long z) {
  const auto wrap = [](long long v) { return static_cast<std::size_t>(v & kLatticeMask); };
  return kPermutation[kPermutation[kPermutation[wrap(x)] ^ wrap(y)] ^ wrap(z)];
}

double noise(Vec3 p, NoiseGenerator generator) {
  const double sum = lattice_sum(p, 0);
  const double v = generator == NoiseGenerator::range_corrected ? 0.5 + sum * kRangeCorrectedScale : sum + 0.5;
  return std::clamp(v, 0.0, 1.0);
}

Vec3 vector_noise(Vec3 p) { return {lattice_sum(p, 0), lattice_sum(p, 1), lattice_sum(p, 2)}; }

// Turbulence(): the first octave at p, then octave k at p·λ^(k−1) weighted ω^(k−1). The range-corrected generator
// uses 2·noise − 0.5 per octave, the first one clipped to [0, 1], as POV-Ray does.
double turbulence(Vec3 p, const Turbulence& t, NoiseGenerator generator) {
  const bool corrected = generator == NoiseGenerator::range_corrected;
  auto octave = [&](Vec3 q) { return corrected ? 2.0 * noise(q, generator) - 0.5 : noise(q, generator); };
  double value = corrected ? std::clamp(octave(p), 0.0, 1.0) : octave(p);
  double lambda = t.lambda, omega = t.omega;
  for (int i = 2; i <= t.octaves; ++i) {
    value += omega * octave(p * lambda);
    lambda *= t.lambda;
    omega *= t.omega;
  }
  return value;
}

Vec3 vector_turbulence(Vec3 p, const Turbulence& t) {
  Vec3 value = vector_noise(p);
  double lambda = t.lambda, omega = t.omega;
  for (int i = 2; i <= t.octaves; ++i) {
    value += vector_noise(p * lambda) * omega;
    lambda *= t.lambda;
    omega *= t.omega;
  }
  return value;
}

}  // namespace povtrace::render

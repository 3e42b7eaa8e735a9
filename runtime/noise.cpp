// See noise.hpp. The lattice, the hashing of lattice points, the S-curve blend, the coefficients and the order of
// the sums follow POV-Ray 3.7's Noise(), DNoise() and SolidNoise() (texture.cpp), so values agree with POV-Ray's
// to the last bit on the same machine arithmetic (no fused multiply-add).
#include "runtime/noise.hpp"

#include "runtime/jitter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace povtrace {

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

// POV-Ray's lattice coefficients are 267 numbers, each the CRC-16 (the reflected polynomial 0xA001, CRC-16/ARC)
// of the big-endian IEEE bytes of the point (0.12345·i, 0.12345·i, 0.12345·i), mapped onto [−1, 1] by
// 2·crc/65535 − 1 and kept to six significant digits (POV-Ray stores them so). We regenerate them by that rule:
// every one of the 267 agrees with POV-Ray 3.7's values (checked once against its texture.cpp, not copied).
constexpr int kCoefficients = 267;
std::uint16_t crc16_arc(const unsigned char* bytes, std::size_t count) {
  std::uint16_t crc = 0;
  for (std::size_t k = 0; k < count; ++k) {
    crc ^= bytes[k];
    for (int bit = 0; bit < 8; ++bit) crc = (crc & 1u) ? static_cast<std::uint16_t>((crc >> 1) ^ 0xA001u) : crc >> 1;
  }
  return crc;
}
double lattice_coefficient(int i) {
  const double v = i * 0.12345;
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  unsigned char bytes[24];
  for (int c = 0; c < 3; ++c)
    for (int b = 0; b < 8; ++b) bytes[c * 8 + b] = static_cast<unsigned char>(bits >> (56 - 8 * b));
  const double unrounded = crc16_arc(bytes, sizeof bytes) * (2.0 / 65535.0) - 1.0;
  char six_digits[32];
  std::snprintf(six_digits, sizeof six_digits, "%g", unrounded);
  return std::strtod(six_digits, nullptr);
}
std::array<double, kCoefficients> make_coefficients() {
  std::array<double, kCoefficients> t{};
  for (int i = 0; i < kCoefficients; ++i) t[static_cast<std::size_t>(i)] = lattice_coefficient(i);
  return t;
}
// Built once at start-up, so that the lookups on the per-sample path carry no initialisation check.
const std::array<double, kCoefficients> kLatticeCoefficients = make_coefficients();

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
// The first of a corner's coefficients: the constant is half of entry h, the ramp's x, y, z slopes entries h+1..h+3;
// vector noise takes its y and z components from h+4 and h+8 on.
std::size_t coefficient_index(std::size_t xy_hash, long long z) {
  return kPermutation[xy_hash ^ static_cast<std::size_t>(z)] & 0xFFu;
}

// One corner's term, summed in POV-Ray's order (INCRSUMP): weight · (c/2 + gx·dx + gy·dy + gz·dz).
double corner_term(const double* c, double weight, double dx, double dy, double dz) {
  return weight * (c[0] * 0.5 + c[1] * dx + c[2] * dy + c[3] * dz);
}

// The 8 corners around a point, with their weights and offsets.
struct Lattice {
  CellCoordinate x, y, z;
  double sx = 0, sy = 0, sz = 0, tx = 0, ty = 0, tz = 0;
  std::size_t ii = 0, ji = 0, ij = 0, jj = 0;   // Hash2d of (x, y), (x+1, y), (x, y+1), (x+1, y+1)
  explicit Lattice(Vec3 p) : x(cell_of(p.x)), y(cell_of(p.y)), z(cell_of(p.z)) {
    sx = s_curve(x.offset), sy = s_curve(y.offset), sz = s_curve(z.offset);
    tx = 1 - sx, ty = 1 - sy, tz = 1 - sz;
    const auto ix = static_cast<std::size_t>(x.index);
    ii = hash(ix, y.index), ji = hash(ix + 1, y.index), ij = hash(ix, y.index + 1), jj = hash(ix + 1, y.index + 1);
  }
};

// The raw scalar sum of POV-Ray's Noise(): the corners at z, then at z + 1, each in the order (x, y), (x+1, y),
// (x, y+1), (x+1, y+1) — floating-point sums depend on the order.
double lattice_sum(Vec3 p) {
  const Lattice l(p);
  const double* c = kLatticeCoefficients.data();
  const double x0 = l.x.offset, y0 = l.y.offset, z0 = l.z.offset, x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
  const double txty = l.tx * l.ty, sxty = l.sx * l.ty, txsy = l.tx * l.sy, sxsy = l.sx * l.sy;
  const long long iz = l.z.index;
  double sum = corner_term(c + coefficient_index(l.ii, iz), txty * l.tz, x0, y0, z0);
  sum += corner_term(c + coefficient_index(l.ji, iz), sxty * l.tz, x1, y0, z0);
  sum += corner_term(c + coefficient_index(l.ij, iz), txsy * l.tz, x0, y1, z0);
  sum += corner_term(c + coefficient_index(l.jj, iz), sxsy * l.tz, x1, y1, z0);
  sum += corner_term(c + coefficient_index(l.ii, iz + 1), txty * l.sz, x0, y0, z1);
  sum += corner_term(c + coefficient_index(l.ji, iz + 1), sxty * l.sz, x1, y0, z1);
  sum += corner_term(c + coefficient_index(l.ij, iz + 1), txsy * l.sz, x0, y1, z1);
  sum += corner_term(c + coefficient_index(l.jj, iz + 1), sxsy * l.sz, x1, y1, z1);
  return sum;
}

// POV-Ray's DNoise(): three sums over the same corners, visited in its own order (at z: (x, y), (x+1, y),
// (x+1, y+1), (x, y+1); at z + 1 the reverse), the y and z components 4 and 8 entries further on.
Vec3 lattice_vector_sum(Vec3 p) {
  const Lattice l(p);
  const double* c = kLatticeCoefficients.data();
  const double x0 = l.x.offset, y0 = l.y.offset, z0 = l.z.offset, x1 = x0 - 1, y1 = y0 - 1, z1 = z0 - 1;
  const double txty = l.tx * l.ty, sxty = l.sx * l.ty, txsy = l.tx * l.sy, sxsy = l.sx * l.sy;
  const long long iz = l.z.index;
  struct Corner {
    std::size_t xy;
    long long z;
    double weight, dx, dy, dz;
  };
  const Corner corners[8] = {
      {l.ii, iz, txty * l.tz, x0, y0, z0},     {l.ji, iz, sxty * l.tz, x1, y0, z0},
      {l.jj, iz, sxsy * l.tz, x1, y1, z0},     {l.ij, iz, txsy * l.tz, x0, y1, z0},
      {l.ij, iz + 1, txsy * l.sz, x0, y1, z1}, {l.jj, iz + 1, sxsy * l.sz, x1, y1, z1},
      {l.ji, iz + 1, sxty * l.sz, x1, y0, z1}, {l.ii, iz + 1, txty * l.sz, x0, y0, z1}};
  Vec3 sum{0, 0, 0};
  for (int k = 0; k < 8; ++k) {
    const Corner& q = corners[k];
    const double* m = c + coefficient_index(q.xy, q.z);
    const Vec3 term{corner_term(m, q.weight, q.dx, q.dy, q.dz), corner_term(m + 4, q.weight, q.dx, q.dy, q.dz),
                    corner_term(m + 8, q.weight, q.dx, q.dy, q.dz)};
    sum = k == 0 ? term : Vec3{sum.x + term.x, sum.y + term.y, sum.z + term.z};
  }
  return sum;
}

// Generator 3 (POV-Ray's SolidNoise): Perlin's gradient noise on a 2048-cell lattice, its unit gradients and
// permutation drawn from the same linear congruential generator (seed 1): gradients by rejection inside the unit
// ball (components ((r mod 4096) − 2048)/2048, kept when 1e-5 ≤ |v|² ≤ 1), then a shuffle of every other entry
// from the top, both tables repeated so that sums of two indices need no modulo.
constexpr int kSolidEntries = 2048;
constexpr double kSolidRollover = 10000000.023157213;   // shifts coordinates positive before the lattice lookup
struct SolidTables {
  std::array<int, 2 * (kSolidEntries + 1)> permutation{};
  std::array<Vec3, 2 * (kSolidEntries + 1)> gradients{};
};
SolidTables make_solid_tables() {
  SolidTables t;
  std::uint32_t state = 1;
  auto next = [&state] {
    state = state * 1812433253u + 12345u;
    return static_cast<int>((state >> 16) & 0x7FFFu);
  };
  for (int i = 0; i < kSolidEntries; ++i) {
    double v[3];
    double s = 0;
    do {
      for (double& component : v)
        component = static_cast<double>(next() % (kSolidEntries << 1) - kSolidEntries) / kSolidEntries;
      s = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
    } while (s > 1.0 || s < 1.0e-5);
    s = 1.0 / std::sqrt(s);
    t.gradients[static_cast<std::size_t>(i)] = {v[0] * s, v[1] * s, v[2] * s};
  }
  for (int i = 0; i < kSolidEntries; ++i) t.permutation[static_cast<std::size_t>(i)] = i;
  for (int i = kSolidEntries; i > 0; i -= 2) {
    const int k = t.permutation[static_cast<std::size_t>(i)];
    const int j = next() % kSolidEntries;
    t.permutation[static_cast<std::size_t>(i)] = t.permutation[static_cast<std::size_t>(j)];
    t.permutation[static_cast<std::size_t>(j)] = k;
  }
  for (std::size_t i = 0; i < kSolidEntries + 2; ++i) {
    t.permutation[kSolidEntries + i] = t.permutation[i];
    t.gradients[kSolidEntries + i] = t.gradients[i];
  }
  return t;
}
const SolidTables kSolidTables = make_solid_tables();

double lerp(double t, double a, double b) { return a + t * (b - a); }

double solid_noise(Vec3 p) {
  const SolidTables& st = kSolidTables;
  int b0[3], b1[3];
  double r0[3], r1[3];
  for (int k = 0; k < 3; ++k) {
    const double t = std::clamp(p[k], -1e15, 1e15) + kSolidRollover;
    const auto it = static_cast<long long>(std::floor(t));
    b0[k] = static_cast<int>(it & (kSolidEntries - 1));
    b1[k] = (b0[k] + 1) & (kSolidEntries - 1);
    r0[k] = t - static_cast<double>(it);
    r1[k] = r0[k] - 1.0;
  }
  const auto perm = [&st](int i) { return st.permutation[static_cast<std::size_t>(i)]; };
  const int i = perm(b0[0]), j = perm(b1[0]);
  const int b00 = perm(i + b0[1]), b10 = perm(j + b0[1]), b01 = perm(i + b1[1]), b11 = perm(j + b1[1]);
  const double sx = s_curve(r0[0]), sy = s_curve(r0[1]), sz = s_curve(r0[2]);
  const auto at = [&st](int g, double x, double y, double z) {
    const Vec3& q = st.gradients[static_cast<std::size_t>(g)];
    return x * q.x + y * q.y + z * q.z;
  };
  double a = lerp(sx, at(b00 + b0[2], r0[0], r0[1], r0[2]), at(b10 + b0[2], r1[0], r0[1], r0[2]));
  double b = lerp(sx, at(b01 + b0[2], r0[0], r1[1], r0[2]), at(b11 + b0[2], r1[0], r1[1], r0[2]));
  const double c = lerp(sy, a, b);
  a = lerp(sx, at(b00 + b1[2], r0[0], r0[1], r1[2]), at(b10 + b1[2], r1[0], r0[1], r1[2]));
  b = lerp(sx, at(b01 + b1[2], r0[0], r1[1], r1[2]), at(b11 + b1[2], r1[0], r1[1], r1[2]));
  const double d = lerp(sy, a, b);
  return lerp(sz, c, d);
}
}  // namespace

std::size_t lattice_hash3(long long x, long long y, long long z) {
  const auto wrap = [](long long v) { return static_cast<std::size_t>(v & kLatticeMask); };
  return kPermutation[kPermutation[kPermutation[wrap(x)] ^ wrap(y)] ^ wrap(z)];
}

double noise(Vec3 p, NoiseGenerator generator) {
  double v = 0;
  switch (generator) {
    case NoiseGenerator::original: v = lattice_sum(p) + 0.5; break;
    // POV-Ray's measured raw range [−1.05242, 0.988997] stretched onto [0, 1].
    case NoiseGenerator::range_corrected: v = (lattice_sum(p) + 1.05242) * 0.48985582; break;
    // Its correction of SolidNoise's bias (range and mean), as POV-Ray applies it.
    case NoiseGenerator::perlin: v = 0.5 * (1.59 * solid_noise(p) + 0.985); break;
  }
  return std::clamp(v, 0.0, 1.0);
}

Vec3 vector_noise(Vec3 p) { return lattice_vector_sum(p); }

// Turbulence(): the first octave at p, then octave k at p·λ^(k−1) weighted ω^(k−1). The range-corrected generator
// uses 2·noise − 0.5 per octave, the first one clipped to [0, 1], as POV-Ray does.
double turbulence(Vec3 p, const Turbulence& t, NoiseGenerator generator) {
  const bool corrected = generator != NoiseGenerator::original;
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

std::uint16_t lattice_permutation_entry(int i) { return kPermutation[static_cast<std::size_t>(i & 0xfff)]; }

}  // namespace povtrace

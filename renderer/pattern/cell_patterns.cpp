// crackle and cells (POV-Ray 3.7 pattern.cpp crackle_pattern, cells_pattern): one random point (crackle) or value
// (cells) per unit cube. POV-Ray draws them from a sequence of 32768 uniform doubles made once by a Mersenne
// Twister (mt19937, default seed 5489) through boost's uniform_real on [0, 1) — each value one 32-bit draw divided
// by 2^32 — indexed by its Hash3d of the cube, so the same generator here gives POV-Ray's cell points exactly.
#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render::patterns {

namespace {
constexpr std::size_t kRandomCount = 32768;
constexpr double kPovEpsilon = 1e-10;

const std::vector<double>& pattern_randoms() {
  static const std::vector<double> values = [] {
    std::mt19937 engine;   // default seed 5489, as boost's
    std::vector<double> v(kRandomCount);
    for (double& x : v) x = static_cast<double>(engine()) / 4294967296.0;
    return v;
  }();
  return values;
}

double pattern_random(std::size_t index) { return pattern_randoms()[index % kRandomCount]; }

// POV-Ray's IntPickInCube: the cube's random point.
Vec3 cell_point(long long x, long long y, long long z) {
  const std::size_t seed = lattice_hash3(x, y, z);
  return {static_cast<double>(x) + pattern_random(seed), static_cast<double>(y) + pattern_random(seed + 1),
          static_cast<double>(z) + pattern_random(seed + 2)};
}

// The cubes whose points can be nearest: the 5×5×5 block around the point's cube without those more than one
// step of 2 away (a "3-D knight move"): 81 of them, in POV-Ray's order.
struct CubeOffset {
  int x, y, z;
};
constexpr std::array<CubeOffset, 81> make_offsets() {
  std::array<CubeOffset, 81> table{};
  std::size_t n = 0;
  for (int x = -2; x <= 2; ++x)
    for (int y = -2; y <= 2; ++y)
      for (int z = -2; z <= 2; ++z)
        if ((x == 2 || x == -2) + (y == 2 || y == -2) + (z == 2 || z == -2) <= 1) table[n++] = {x, y, z};
  return table;
}
constexpr auto kOffsets = make_offsets();

double metric_sum(Vec3 d, double metric) {
  if (metric == 2) return d.x * d.x + d.y * d.y + d.z * d.z;
  if (metric == 1) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
  return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) + std::pow(std::fabs(d.z), metric);
}

// The metric's sum back to a distance (the square root for 2, nothing for 1, the 1/metric power otherwise).
double distance_of(double sum, double metric) {
  if (metric == 2) return std::sqrt(sum);
  if (metric == 1) return sum;
  return std::pow(sum, 1.0 / metric);
}
}  // namespace

double crackle(Vec3 p, const CrackleParams& c, NoiseGenerator generator) {
  // floor(x − ε), not POV-Ray's FLOOR: no mirror image about zero.
  const auto fx = static_cast<long long>(std::floor(p.x - kPovEpsilon));
  const auto fy = static_cast<long long>(std::floor(p.y - kPovEpsilon));
  const auto fz = static_cast<long long>(std::floor(p.z - kPovEpsilon));
  std::array<double, 3> nearest{};
  std::array<Vec3, 3> first{};
  for (std::size_t i = 0; i < 3; ++i) {
    first[i] = cell_point(fx + kOffsets[i].x, fy + kOffsets[i].y, fz + kOffsets[i].z);
    nearest[i] = metric_sum(first[i] - p, c.metric);
  }
  // The first three sorted as POV-Ray does (the nearest index follows the first two swaps only).
  std::size_t nearest_index = 0;
  if (nearest[1] < nearest[0]) { std::swap(nearest[0], nearest[1]); nearest_index = 1; }
  if (nearest[2] < nearest[0]) { std::swap(nearest[0], nearest[2]); nearest_index = 2; }
  if (nearest[2] < nearest[1]) std::swap(nearest[1], nearest[2]);
  Vec3 nearest_point = first[nearest_index];
  for (std::size_t i = 3; i < kOffsets.size(); ++i) {
    const Vec3 q = cell_point(fx + kOffsets[i].x, fy + kOffsets[i].y, fz + kOffsets[i].z);
    const double s = metric_sum(q - p, c.metric);
    if (s < nearest[0]) {
      nearest = {s, nearest[0], nearest[1]};
      nearest_point = q;
    } else if (s < nearest[1]) {
      nearest = {nearest[0], s, nearest[1]};
    } else if (s < nearest[2]) {
      nearest[2] = s;
    }
  }
  if (c.offset != 0) {
    const double add = c.metric == 2 ? c.offset * c.offset : c.metric == 1 ? c.offset : std::pow(c.offset, c.metric);
    for (double& s : nearest) s += add;
  }
  double value;
  if (c.solid) {
    value = noise(nearest_point, generator);   // povtrace's noise table: cell shades differ from POV-Ray's
  } else {
    value = c.form.x * distance_of(nearest[0], c.metric) + c.form.y * distance_of(nearest[1], c.metric) +
            c.form.z * distance_of(nearest[2], c.metric);
  }
  return std::max(std::min(value, 1.0), 0.0);
}

// cells: the cube's random value (floor(x + ε) per axis).
double cells(Vec3 p) {
  const auto cell = [](double v) { return static_cast<long long>(std::floor(v + kPovEpsilon)); };
  return std::min(pattern_random(lattice_hash3(cell(p.x), cell(p.y), cell(p.z))), 1.0);
}

}  // namespace povtrace::render::patterns

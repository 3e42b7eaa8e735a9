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

// The 81 cell points around a cube, in kOffsets order. Computing them is most of crackle's cost and neighbouring
// evaluations (media samples along a ray, adjacent pixels) mostly fall in cubes just seen, so each thread keeps
// the points of the cubes it used last (as POV-Ray keeps a crackle cache per thread): a direct-mapped table of 256
// cubes (500 kB per thread), enough for a media sampled across a few crackle cells of two patterns in turn.
constexpr std::size_t kCubeCacheSize = 256;
const std::array<Vec3, 81>& cube_points(long long x, long long y, long long z) {
  struct Entry {
    long long x = 0, y = 0, z = 0;
    bool valid = false;
    std::array<Vec3, 81> points;
  };
  thread_local std::vector<Entry> table(kCubeCacheSize);
  const auto hash = static_cast<std::size_t>((x * 73856093LL) ^ (y * 19349663LL) ^ (z * 83492791LL));
  const std::size_t slot = hash & (kCubeCacheSize - 1);
  Entry& e = table[slot];
  if (!e.valid || e.x != x || e.y != y || e.z != z) {
    for (std::size_t i = 0; i < kOffsets.size(); ++i)
      e.points[i] = cell_point(x + kOffsets[i].x, y + kOffsets[i].y, z + kOffsets[i].z);
    e.x = x;
    e.y = y;
    e.z = z;
    e.valid = true;
  }
  return e.points;
}

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
// The three smallest metric sums from p to the points, and the nearest point, found in POV-Ray's order: the first
// three sorted as POV-Ray does (the nearest index follows the first two swaps only), then the others in turn.
struct Nearest {
  std::array<double, 3> sums{};
  Vec3 point;
};
template <class Sum>
Nearest nearest_three(const std::array<Vec3, 81>& points, Vec3 p, Sum sum) {
  double a = sum(points[0] - p), b = sum(points[1] - p), c = sum(points[2] - p);
  std::size_t nearest_index = 0;
  if (b < a) { std::swap(a, b); nearest_index = 1; }
  if (c < a) { std::swap(a, c); nearest_index = 2; }
  if (c < b) std::swap(b, c);
  Vec3 nearest_point = points[nearest_index];
  for (std::size_t i = 3; i < points.size(); ++i) {
    const double s = sum(points[i] - p);
    if (s < c) {   // most points are further than the third: one comparison for them
      if (s < a) {
        c = b;
        b = a;
        a = s;
        nearest_point = points[i];
      } else if (s < b) {
        c = b;
        b = s;
      } else {
        c = s;
      }
    }
  }
  return Nearest{{a, b, c}, nearest_point};
}

}  // namespace

double pattern_random(std::size_t index) { return pattern_randoms()[index % kRandomCount]; }

double crackle(Vec3 p, const CrackleParams& c, NoiseGenerator generator) {
  // floor(x − ε), not POV-Ray's FLOOR: no mirror image about zero.
  const auto fx = static_cast<long long>(std::floor(p.x - kPovEpsilon));
  const auto fy = static_cast<long long>(std::floor(p.y - kPovEpsilon));
  const auto fz = static_cast<long long>(std::floor(p.z - kPovEpsilon));
  const std::array<Vec3, 81>& points = cube_points(fx, fy, fz);
  Nearest n;
  if (c.metric == 2) n = nearest_three(points, p, [](Vec3 d) { return d.x * d.x + d.y * d.y + d.z * d.z; });
  else n = nearest_three(points, p, [&c](Vec3 d) { return metric_sum(d, c.metric); });
  std::array<double, 3>& nearest = n.sums;
  const Vec3 nearest_point = n.point;
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

Vec3 facets(Vec3 normal, Vec3 p, double coords, double size, double metric) {
  normal = normalize(normal);
  const double scale = size < 1e-6 ? 1e6 : 1.0 / size;
  const Vec3 tv = (coords != 0.0 ? p : normal) * scale;
  const auto fx = static_cast<long long>(std::floor(tv.x - kPovEpsilon));
  const auto fy = static_cast<long long>(std::floor(tv.y - kPovEpsilon));
  const auto fz = static_cast<long long>(std::floor(tv.z - kPovEpsilon));
  const std::array<Vec3, 81>& points = cube_points(fx, fy, fz);
  // POV-Ray's metric 1 sums the differences without their absolute values; the first nearest point wins ties.
  const auto sum = [metric](Vec3 d) {
    if (metric == 2) return d.x * d.x + d.y * d.y + d.z * d.z;
    if (metric == 1) return d.x + d.y + d.z;
    return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) + std::pow(std::fabs(d.z), metric);
  };
  double nearest = sum(points[0] - tv);
  Vec3 chosen = points[0];
  for (std::size_t i = 1; i < points.size(); ++i) {
    const double s = sum(points[i] - tv);
    if (s < nearest) {
      nearest = s;
      chosen = points[i];
    }
  }
  if (coords == 0.0) return chosen;
  Vec3 pert = vector_noise(chosen);
  pert -= normal * dot(pert, normal);
  return normal + pert * coords;
}

// cells: the cube's random value (floor(x + ε) per axis).
double cells(Vec3 p) {
  const auto cell = [](double v) { return static_cast<long long>(std::floor(v + kPovEpsilon)); };
  return std::min(pattern_random(lattice_hash3(cell(p.x), cell(p.y), cell(p.z))), 1.0);
}

}  // namespace povtrace::render::patterns

#include "renderer/radiosity/pretrace.hpp"

#include <algorithm>
#include <cmath>
#include <random>

namespace povtrace::render::radiosity {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON in the pass count
constexpr int kMaxPasses = 252;      // the pass ids 1 … 252 POV-Ray's octree can tag
}  // namespace

std::vector<double> pretrace_cell_sizes(int width, int height, double pretrace_start, double pretrace_end) {
  const double m = std::max(width, height);
  double start = m * pretrace_start;
  const double end = std::max(1.0, m * pretrace_end);
  int passes = static_cast<int>(std::floor(std::log(start / end) / std::log(2.0) + (1.0 - kEpsilon))) + 1;
  if (passes > kMaxPasses) {
    passes = kMaxPasses;
    start = end * std::pow(2.0, passes);
  }
  std::vector<double> sizes;
  for (int p = 0; p < passes; ++p)
    sizes.push_back(std::max(start * static_cast<double>(std::pow(0.5f, static_cast<float>(p))), end));
  return sizes;
}

const std::array<double, PretraceJitter::size>& PretraceJitter::table() {
  static const std::array<double, size> values = [] {
    std::array<double, size> t{};
    std::mt19937 engine;   // default seed 5489, as a default-constructed boost::mt19937
    for (double& v : t) v = static_cast<double>(engine()) / 4294967296.0 * 2.0 + -1.0;
    return t;
  }();
  return values;
}

PretraceJitter::PretraceJitter() { table(); }

void PretraceJitter::seed(int pass, int serial) {
  index_ = static_cast<int>((static_cast<long long>(pass) * 17 + static_cast<long long>(serial) * 13) % size);
}

double PretraceJitter::next() {
  index_ = (index_ + 1) % size;
  return table()[static_cast<std::size_t>(index_)];
}

std::vector<PretracePoint> pretrace_points(const BlockRect& block, const PretraceBlockState& state, SubBlock sub,
                                           double size, PretraceJitter& jitter) {
  const double start_x = std::ceil((block.left - 0.5) / size) * size;
  const double start_y = std::ceil((block.top - 0.5) / size) * size;
  const double amount = std::min(1.0, size / 2.0);
  const double offset = (size - 1.0) / 2.0;
  const double sub_x0 = block.left + static_cast<double>(block.width()) * sub.x / state.sub_count_x;
  const double sub_x1 = sub_x0 + static_cast<double>(block.width()) / state.sub_count_x;
  const double sub_y0 = block.top + static_cast<double>(block.height()) * sub.y / state.sub_count_y;
  const double sub_y1 = sub_y0 + static_cast<double>(block.height()) / state.sub_count_y;
  std::vector<PretracePoint> points;
  for (double y = start_y; y < sub_y1; y += size) {
    if (y < sub_y0) continue;
    for (double x = start_x; x < sub_x1; x += size) {
      if (x < sub_x0) continue;
      const double jy = jitter.next();
      const double jx = jitter.next();
      points.push_back({x + offset + amount * jx, y + offset + amount * jy});
    }
  }
  return points;
}

bool pretrace_again(int points, long queries, float reuse, int coverage) {
  if (points < 9) return true;
  if (queries == 0) return false;
  if (coverage != 0 && reuse / static_cast<float>(queries) >= static_cast<float>(coverage)) return false;
  return true;
}

int pretrace_split(int extent, double next_size, int sub_count, int coverage) {
  if (coverage == 0) return 1;
  const auto next_points = static_cast<unsigned>((extent + next_size - 1) / next_size);
  return std::max(1, static_cast<int>(std::floor(static_cast<double>(next_points) / (sub_count * 4.0))));
}

}  // namespace povtrace::render::radiosity

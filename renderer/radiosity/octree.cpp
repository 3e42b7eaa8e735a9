#include "renderer/radiosity/octree.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cfloat>
#include <climits>
#include <cmath>

namespace povtrace::render::radiosity {

namespace {

constexpr int unit_size_code = 127;   // the exponent field of 1.0f

// The largest power of two ≤ w after rounding w to single precision; 0 for 0 and for subnormal results (POV-Ray
// clears the mantissa bits of the float, which zeroes a subnormal).
double power_of_two_floor(double w) {
  const float f = static_cast<float>(w);
  if (!(f >= FLT_MIN)) return 0;
  int exponent = 0;
  std::frexp(f, &exponent);   // f = m·2^exponent, m in [½, 1)
  return std::ldexp(1.0, exponent - 1);
}

int size_code_of(double side) {
  int exponent = 0;
  std::frexp(side, &exponent);
  return exponent - 1 + unit_size_code;
}

double max3(double a, double b, double c) { return std::max(a, std::max(b, c)); }

bool axis_covers(double p, int i, double side) {
  return std::fabs(p + octree_bias - (static_cast<double>(i) + 0.5) * side) < side;
}

// The positions along one axis whose node of this side covers coordinate p: mathematically ⌊t⌋ − 1 … ⌊t⌋ + 1
// with t = (p + 1e7)/side (two of them, or one on a boundary); ±2 are tested too, against rounding.
struct AxisPositions {
  std::array<int, 5> at{};
  int count = 0;
};
AxisPositions covering_positions(double p, double side) {
  AxisPositions out;
  const double t = std::floor((p + octree_bias) / side);
  if (!(t > static_cast<double>(INT_MIN) + 2 && t < static_cast<double>(INT_MAX) - 2)) return out;
  for (int i = static_cast<int>(t) - 2; i <= static_cast<int>(t) + 2; ++i)
    if (axis_covers(p, i, side)) out.at[static_cast<std::size_t>(out.count++)] = i;
  return out;
}

}  // namespace

double node_side(int size_code) {
  assert(size_code >= 1 && size_code <= 254);
  return std::ldexp(1.0, size_code - unit_size_code);
}

bool node_covers(const NodeKey& node, Vec3 p) {
  const double side = node_side(node.size_code);
  return axis_covers(p.x, node.x, side) && axis_covers(p.y, node.y, side) && axis_covers(p.z, node.z, side);
}

NodeKey parent_node(const NodeKey& node) {
  const auto half = [](int i) { return i >= 0 ? (i >> 1) : (i + 1) / 2; };
  return {node.size_code + 1, half(node.x), half(node.y), half(node.z)};
}

NodeKey filing_node(Vec3 centre, double radius) {
  const Vec3 lo{centre.x - radius, centre.y - radius, centre.z - radius};
  const Vec3 hi{centre.x + radius, centre.y + radius, centre.z + radius};
  double side = power_of_two_floor(max3(hi.x - lo.x, hi.y - lo.y, hi.z - lo.z));
  if (side == 0) side = 1;
  const double farthest = max3(std::fabs(lo.x), std::fabs(lo.y), std::fabs(lo.z)) + octree_bias;
  while (farthest / side > octree_max_index) side *= 2;
  const Vec3 mid = (lo + hi) / 2;
  NodeKey node{size_code_of(side), static_cast<int>(std::floor((mid.x + octree_bias) / side)),
               static_cast<int>(std::floor((mid.y + octree_bias) / side)),
               static_cast<int>(std::floor((mid.z + octree_bias) / side))};
  while (!node_covers(node, lo) || !node_covers(node, hi)) node = parent_node(node);
  return node;
}

double filing_factor(double error_bound, int depth) {
  const double overfill = depth == 0 ? 1.0 : 8.0;
  return error_bound * std::pow(2.0, depth) / overfill;
}

std::size_t NodeKeyHash::operator()(const NodeKey& k) const {
  std::size_t h = static_cast<std::size_t>(k.size_code);
  for (const int v : {k.x, k.y, k.z}) h = h * 0x9E3779B97F4A7C15ull + static_cast<std::uint32_t>(v);
  return h ^ (h >> 29);
}

void NodeIndex::insert(const NodeKey& node, std::uint32_t id) {
  std::vector<std::uint32_t>& list = nodes_[node];
  assert(list.empty() || list.back() < id);
  list.push_back(id);
  const auto level = std::lower_bound(levels_.begin(), levels_.end(), node.size_code);
  if (level == levels_.end() || *level != node.size_code) levels_.insert(level, node.size_code);
  ++count_;
}

void NodeIndex::covering_at_level(int size_code, Vec3 p, std::vector<std::uint32_t>& ids) const {
  const double side = node_side(size_code);
  const AxisPositions xs = covering_positions(p.x, side);
  const AxisPositions ys = covering_positions(p.y, side);
  const AxisPositions zs = covering_positions(p.z, side);
  for (int a = 0; a < xs.count; ++a)
    for (int b = 0; b < ys.count; ++b)
      for (int c = 0; c < zs.count; ++c) {
        const NodeKey key{size_code, xs.at[static_cast<std::size_t>(a)], ys.at[static_cast<std::size_t>(b)],
                          zs.at[static_cast<std::size_t>(c)]};
        const auto found = nodes_.find(key);
        if (found != nodes_.end()) ids.insert(ids.end(), found->second.begin(), found->second.end());
      }
}

void NodeIndex::covering(Vec3 p, std::vector<std::uint32_t>& ids) const {
  const std::size_t first = ids.size();
  for (const int level : levels_) covering_at_level(level, p, ids);
  std::sort(ids.begin() + static_cast<std::ptrdiff_t>(first), ids.end());
}

void NodeIndex::clear() {
  nodes_.clear();
  levels_.clear();
  count_ = 0;
}

}  // namespace povtrace::render::radiosity

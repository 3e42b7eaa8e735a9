#include "renderer/radiosity/octree.hpp"

#include <algorithm>
#include <cassert>
#include <cfloat>
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

namespace {
// The ancestor of `node` of size code `size_code` (≥ the node's own).
NodeKey ancestor_at(NodeKey node, int size_code) {
  while (node.size_code < size_code) node = parent_node(node);
  return node;
}
}  // namespace

std::uint32_t NodeIndex::child_of(std::uint32_t parent, const NodeKey& key) {
  for (const std::uint32_t c : nodes_[parent].children)
    if (nodes_[c].key == key) return c;
  const auto made = static_cast<std::uint32_t>(nodes_.size());
  nodes_.push_back(Node{key, node_side(key.size_code), {}, {}});
  nodes_[parent].children.push_back(made);
  return made;
}

void NodeIndex::insert(const NodeKey& node, std::uint32_t id) {
  if (nodes_.empty()) {
    nodes_.push_back(Node{node, node_side(node.size_code), {}, {}});
    root_ = 0;
  }
  // Grow the root until it is the node or one of its ancestors (the positions converge within ~32 parents).
  while (nodes_[root_].key.size_code < node.size_code ||
         ancestor_at(node, nodes_[root_].key.size_code) != nodes_[root_].key) {
    const auto grown = static_cast<std::uint32_t>(nodes_.size());
    const NodeKey up = parent_node(nodes_[root_].key);
    nodes_.push_back(Node{up, node_side(up.size_code), {}, {root_}});
    root_ = grown;
  }
  std::uint32_t at = root_;
  for (int code = nodes_[root_].key.size_code - 1; code >= node.size_code; --code)
    at = child_of(at, ancestor_at(node, code));
  nodes_[at].samples.push_back(id);
  ++count_;
}

void NodeIndex::walk(std::uint32_t node, Vec3 p, std::vector<std::uint32_t>& ids) const {
  const Node& n = nodes_[node];
  ids.insert(ids.end(), n.samples.begin(), n.samples.end());
  for (const std::uint32_t c : n.children) {
    const Node& child = nodes_[c];
    if (axis_covers(p.x, child.key.x, child.side) && axis_covers(p.y, child.key.y, child.side) &&
        axis_covers(p.z, child.key.z, child.side))
      walk(c, p, ids);
  }
}

void NodeIndex::covering(Vec3 p, std::vector<std::uint32_t>& ids) const {
  if (!nodes_.empty() && node_covers(nodes_[root_].key, p)) walk(root_, p, ids);
}

void NodeIndex::clear() {
  nodes_.clear();
  root_ = 0;
  count_ = 0;
}

}  // namespace povtrace::render::radiosity

// Which cached samples a radiosity lookup is offered (docs/issue19-study.md §3.5; POV-Ray 3.7 source/backend/
// support/octree.cpp ot_index_sphere, ot_index_box, ot_point_in_node, ot_parent, ot_dist_traverse). POV-Ray
// files each sample in one cubic octree node chosen from the sample's position and filing radius, and a lookup
// walks only nodes that "cover" the query point. Since a node's parent covers every point the node covers, the
// samples a lookup sees are exactly those whose node covers the point. This index is such a tree: nodes hold their
// samples, a lookup descends from the root into the children that cover the point.
//
// (POV-Ray's parent of a negative position i is (i + 1)/2 truncated, whose cube need not contain the child's; such
// positions mean coordinates below −1e7, where the walk may miss a sample the "covers" rule would offer.)
//
// POV-Ray's walk never tests the root node itself, so samples filed exactly at the current root are offered to
// every lookup; povtrace does not reproduce that artefact of insertion history (the reuse test of weights.hpp
// rejects such far samples anyway, except for weak rays and bounces, where the node test hides samples too).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "scene/vecmath.hpp"

namespace povtrace::render::radiosity {

// A node: a cube of side 2^(size_code − 127) (size_code is the IEEE single-precision exponent field of the side,
// as POV-Ray stores it: 127 = side 1, 126 = side ½), at integer position (x, y, z) in units of its side, in
// coordinates shifted by +1e7 so that ordinary scenes have non-negative positions.
struct NodeKey {
  int size_code = 127;
  int x = 0, y = 0, z = 0;
  friend bool operator==(const NodeKey&, const NodeKey&) = default;
};

inline constexpr double octree_bias = 1e7;        // OT_BIAS, added to every coordinate before dividing
inline constexpr double octree_max_index = 1e9;   // node positions stay below this (SAFE_METHOD's guard)

// The side of a node of this size code (1 ≤ code ≤ 254).
double node_side(int size_code);

// The node covers p when p lies in its cube expanded by half a side on every face:
// |p + 1e7 − (i + ½)·side| < side on every axis (in this order of operations).
bool node_covers(const NodeKey& node, Vec3 p);

// The parent node: size + 1, each position halved (x ≥ 0: x >> 1; x < 0: (x + 1)/2 truncated, POV-Ray's choice).
NodeKey parent_node(const NodeKey& node);

// The node a sample with centre `centre` and filing radius `radius` is filed in: for the box centre ± radius,
// side = the largest power of two ≤ the box's largest width rounded to single precision (1 when that is 0 or
// subnormal), doubled while (largest |low corner coordinate| + 1e7)/side > 1e9; position ⌊(box centre + 1e7)/side⌋;
// then the parent is taken until the node covers both box corners.
NodeKey filing_node(Vec3 centre, double radius);

// The factor from a sample's clamped harmonic-mean radius r (the double value, before it is stored in single
// precision) to its filing radius: E0·2^depth / overfill, overfill 1 at depth 0 and 8 deeper. E0 is the scene's
// error_bound, never multiplied by low_error_factor.
double filing_factor(double error_bound, int depth);

// Sample ids grouped by node, in a tree of nodes (each node's parent is parent_node of it).
class NodeIndex {
 public:
  // File sample `id` under `node`.
  void insert(const NodeKey& node, std::uint32_t id);
  // Append to `ids` the id of every sample whose node covers p, in a fixed order for a given insertion history
  // (the tree walk's: a node's samples in insertion order, then its children's in the order they were created).
  void covering(Vec3 p, std::vector<std::uint32_t>& ids) const;
  std::size_t size() const { return count_; }
  bool empty() const { return count_ == 0; }
  void clear();

 private:
  struct Node {
    NodeKey key;
    double side = 1;   // node_side(key.size_code)
    std::vector<std::uint32_t> samples;
    std::vector<std::uint32_t> children;   // indices into nodes_
  };
  void walk(std::uint32_t node, Vec3 p, std::vector<std::uint32_t>& ids) const;
  std::uint32_t child_of(std::uint32_t parent, const NodeKey& key);

  std::vector<Node> nodes_;
  std::uint32_t root_ = 0;   // meaningful when nodes_ is not empty
  std::size_t count_ = 0;
};

}  // namespace povtrace::render::radiosity

// A bounding volume hierarchy over the triangles of one mesh, in the mesh's object space: the second level of the
// two-level BVH (the scene's Accelerator holds one primitive per placed mesh; a placement's rays are carried into
// object space and walk this tree, which every placement shares).
//
// Compact on purpose, for meshes of millions of triangles: 32-byte nodes with single-precision bounds (the
// vertices are single precision, so the bounds are exact) and one 4-byte triangle index per triangle — about
// 20 bytes per triangle with leaves of up to 4 triangles. Built with binned SAH like the scene's Accelerator.
#pragma once

#include <cassert>
#include <cstdint>
#include <vector>

#include "renderer/geometry.hpp"

namespace povtrace::render {

class TriangleBvh {
 public:
  struct Node {
    float lo[3], hi[3];
    std::uint32_t first = 0;   // leaf: first index into order(); inner: index of the right child (left = this + 1)
    std::uint16_t count = 0;   // leaf: number of triangles; 0 for inner nodes
    std::uint16_t axis = 0;    // inner: split axis, for front-to-back order
  };

  TriangleBvh() = default;
  // `vertices`: x y z per vertex; `faces`: three vertex indices per triangle.
  TriangleBvh(const std::vector<float>& vertices, const std::vector<std::uint32_t>& faces);

  Bounds bounds() const;
  const std::vector<std::uint32_t>& order() const { return order_; }
  const std::vector<Node>& nodes() const { return nodes_; }

  // Calls test(triangle) for every triangle of every leaf whose box the ray meets within [t_min, t_max], nearer
  // subtrees first. test may lower t_max (a nearest-hit search), after which farther subtrees are skipped; it
  // returns false to stop the walk.
  template <class Test>
  void traverse(const Ray& ray, double t_min, double& t_max, Test&& test) const;

 private:
  std::vector<Node> nodes_;
  std::vector<std::uint32_t> order_;
};

namespace detail {
struct BvhSlabRay {
  Vec3 origin, inv_direction;
  bool negative[3];
  explicit BvhSlabRay(const Ray& ray) : origin(ray.origin) {
    for (int i = 0; i < 3; ++i) {
      inv_direction[i] = 1.0 / ray.direction[i];
      negative[i] = ray.direction[i] < 0 || (ray.direction[i] == 0 && 1.0 / ray.direction[i] < 0);
    }
  }
};
// Entry depth of the ray into the node's box if it overlaps [t_min, t_max]; NaN slab depths (a ray lying in a slab
// plane) leave the interval unchanged. The exit is inflated slightly so rounding never culls a reported root.
inline bool node_hit(const TriangleBvh::Node& n, const BvhSlabRay& r, double t_min, double t_max, double& t_entry) {
  double t_near = t_min, t_far = t_max;
  for (int i = 0; i < 3; ++i) {
    const double lo = ((r.negative[i] ? n.hi[i] : n.lo[i]) - r.origin[i]) * r.inv_direction[i];
    const double hi = ((r.negative[i] ? n.lo[i] : n.hi[i]) - r.origin[i]) * r.inv_direction[i];
    if (lo > t_near) t_near = lo;
    if (hi * (1.0 + 1e-12) + 1e-12 < t_far) t_far = hi * (1.0 + 1e-12) + 1e-12;
  }
  t_entry = t_near;
  return t_near <= t_far;
}
}  // namespace detail

template <class Test>
void TriangleBvh::traverse(const Ray& ray, double t_min, double& t_max, Test&& test) const {
  if (nodes_.empty()) return;
  const detail::BvhSlabRay slab(ray);
  double entry = 0;
  if (!detail::node_hit(nodes_[0], slab, t_min, t_max, entry)) return;
  constexpr int stack_size = 64;
  std::uint32_t stack[stack_size];
  double stack_entry[stack_size];
  int top = 0;
  std::uint32_t node = 0;
  for (;;) {
    const Node& n = nodes_[node];
    if (n.count > 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k)
        if (!test(order_[k])) return;
    } else {
      std::uint32_t near_child = node + 1, far_child = n.first;
      if (slab.negative[n.axis]) std::swap(near_child, far_child);
      double t_near = 0, t_far = 0;
      const bool hit_near = detail::node_hit(nodes_[near_child], slab, t_min, t_max, t_near);
      const bool hit_far = detail::node_hit(nodes_[far_child], slab, t_min, t_max, t_far);
      if (hit_near && hit_far) {
        assert(top < stack_size);   // the build bounds the depth below 64
        stack_entry[top] = t_far;
        stack[top++] = far_child;
      }
      if (hit_near || hit_far) {
        node = hit_near ? near_child : far_child;
        continue;
      }
    }
    do {
      if (top == 0) return;
      --top;
    } while (stack_entry[top] > t_max);
    node = stack[top];
  }
}

}  // namespace povtrace::render

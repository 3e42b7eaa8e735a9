// Accelerator: a binned-SAH bounding volume hierarchy over the bounded primitives, plus a flat list of unbounded
// ones (planes) that every ray tests.
//
// Build: top-down; at each node the SAH cost A_left·N_left + A_right·N_right is evaluated at the 15 boundaries of
// 16 centroid bins on each of the three axes and the cheapest is taken. Nodes with at most 4 primitives become
// leaves. Below depth 32 (pathological distributions) the split switches to the object median, which bounds the
// depth at 32 + log2(n) < 64 and so fits the fixed traversal stack. Nodes are stored depth first: the left child of
// node i is i + 1, Node::first holds the right child. 100,000 primitives build in a few tens of milliseconds.
//
// Conservativeness: each primitive's world bounds are padded by 1e-7 of their magnitude (+1e-9 absolute) and the
// slab exit depth is inflated by 1e-12 relative, so a root a shape reports is never culled by rounding in the box
// test. Slabs use a precomputed reciprocal direction; 0 · inf = NaN cases (ray in a slab plane, parallel) are
// absorbed by NaN-ignoring min/max.
//
// Traversal: iterative, fixed 64-entry stack. At an inner node both children's boxes are tested; the near child (by
// the sign of the ray direction on the node's split axis) is visited first and the far one pushed with its entry
// depth, so it is skipped when a nearer hit has been found meanwhile. The current nearest depth shrinks the search
// interval. Ties in depth go to the lower primitive index, so
// closest_hit returns exactly what closest_hit_brute_force returns.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "renderer/accel/binned_sah.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

namespace {

constexpr std::uint32_t max_leaf_size = 4;
constexpr int sah_depth_limit = 32;  // deeper than this: median splits only (bounds the tree depth)
constexpr int stack_size = 64;
constexpr double exit_slack = 1.0 + 1e-12;

Bounds padded(Bounds b) {
  double magnitude = 1.0;
  for (int i = 0; i < 3; ++i) magnitude = std::max({magnitude, std::abs(b.lo[i]), std::abs(b.hi[i])});
  const double pad = magnitude * 1e-7 + 1e-9;
  const Vec3 e{pad, pad, pad};
  return Bounds{b.lo - e, b.hi + e};
}

// Ray prepared for slab tests.
struct SlabRay {
  Vec3 origin;
  Vec3 inv_direction;
  bool negative[3];
  explicit SlabRay(const Ray& ray) : origin(ray.origin) {
    for (int i = 0; i < 3; ++i) {
      inv_direction[i] = 1.0 / ray.direction[i];
      negative[i] = std::signbit(ray.direction[i]);
    }
  }
};

// Does the ray's interval [t_min, t_max] overlap the box? On overlap, t_entry receives the entry depth (at least
// t_min). Comparisons are written so that a NaN slab depth (origin exactly in a slab plane of an axis the ray is
// parallel to: 0 · inf) leaves the interval unchanged.
inline bool slab_hit(const Bounds& b, const SlabRay& r, double t_min, double t_max, double& t_entry) {
  double t_near = t_min;
  double t_far = t_max;
  for (int i = 0; i < 3; ++i) {
    const double lo = ((r.negative[i] ? b.hi[i] : b.lo[i]) - r.origin[i]) * r.inv_direction[i];
    const double hi = ((r.negative[i] ? b.lo[i] : b.hi[i]) - r.origin[i]) * r.inv_direction[i];
    if (lo > t_near) t_near = lo;
    if (hi * exit_slack < t_far) t_far = hi * exit_slack;
  }
  t_entry = t_near;
  return t_near <= t_far;
}

// Closest-hit bookkeeping shared by the BVH walk and the brute-force reference.
struct Nearest {
  double t;
  std::uint32_t primitive = ~0u;
  SurfaceHit surface;
};

// Considers the nearest root of primitive i above t_min; keeps it if nearer than the current best (ties: lower
// index wins). Shadow rays see only shadow-casting primitives.
template <bool shadow_casters_only = false>
inline void consider(const Primitive& p, std::uint32_t i, const Ray& ray, double t_min, Nearest& best) {
  if (p.hidden_from & ray.kind) return;   // no_image / no_reflection (always 0 for scenes without them)
  if (shadow_casters_only && !p.casts_shadow) return;
  // A hit at exactly the best depth may still win the tie, so the search interval ends just above it.
  const double t_max = best.primitive != ~0u && i < best.primitive ? std::nextafter(best.t, tolerance::bound_huge)
                                                                   : best.t;
  if (!p.data) {   // few roots, depth-sorted: the first one above t_min decides (no SurfaceHit until it wins)
    const Intersections xs = intersect_all(p, ray);
    for (int k = 0; k < xs.count; ++k) {
      if (!(xs.t[k] > t_min)) continue;
      if (!(xs.t[k] < t_max)) return;
      best.t = xs.t[k];
      best.primitive = i;
      best.surface = SurfaceHit{xs.t[k], &p, xs.element[k], 0, 0};
      return;
    }
    return;
  }
  const std::optional<SurfaceHit> hit = nearest_hit(p, ray, t_min, t_max);
  if (!hit) return;
  best.t = hit->t;
  best.primitive = i;
  best.surface = *hit;
}

Hit to_hit(const Nearest& best) {
  Hit h;
  if (best.primitive != ~0u) {
    h.t = best.t;
    h.primitive = best.primitive;
    h.surface = best.surface;
  }
  return h;
}

}  // namespace

Accelerator::Accelerator(std::vector<Primitive> primitives) : primitives_(std::move(primitives)) {
  const auto n = static_cast<std::uint32_t>(primitives_.size());
  std::vector<Bounds> bounds(n);
  std::vector<Vec3> centroids(n);
  order_.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const Bounds b = world_bounds(primitives_[i]);
    if (!b.finite()) {
      unbounded_.push_back(i);
      continue;
    }
    bounds[i] = padded(b);
    centroids[i] = b.centre();
    order_.push_back(i);
  }
  if (order_.empty()) return;
  nodes_.reserve(2 * order_.size() / max_leaf_size + 2);
  build_node(0, static_cast<std::uint32_t>(order_.size()), 0, bounds, centroids);
}

std::uint32_t Accelerator::build_node(std::uint32_t begin, std::uint32_t end, int depth,
                                      const std::vector<Bounds>& bounds, const std::vector<Vec3>& centroids) {
  const auto index = static_cast<std::uint32_t>(nodes_.size());
  nodes_.emplace_back();
  Bounds node_bounds;
  Bounds centroid_bounds;
  for (std::uint32_t k = begin; k < end; ++k) {
    node_bounds.extend(bounds[order_[k]]);
    centroid_bounds.extend(centroids[order_[k]]);
  }
  nodes_[index].bounds = node_bounds;
  const std::uint32_t count = end - begin;
  if (count <= max_leaf_size) {
    nodes_[index].first = begin;
    nodes_[index].count = static_cast<std::uint16_t>(count);
    return index;
  }

  const Vec3 extent = centroid_bounds.hi - centroid_bounds.lo;
  int axis = 0;
  if (extent.y > extent[axis]) axis = 1;
  if (extent.z > extent[axis]) axis = 2;
  std::uint32_t mid = begin + count / 2;
  bool split_done = false;

  if (extent[axis] > 0 && depth < sah_depth_limit) {
    // Binned SAH on every axis with a non-degenerate centroid extent.
    // The axis as a member pointer: Vec3's operator[] chooses among x, y and z with a branch at every call.
    const auto binner_for = [&centroids, &centroid_bounds, &extent](int a) {
      double Vec3::* const coordinate = a == 0 ? &Vec3::x : (a == 1 ? &Vec3::y : &Vec3::z);
      const double lo = centroid_bounds.lo[a], scale = sah_bin_count / extent[a];
      return [c = centroids.data(), coordinate, lo, scale](std::uint32_t i) {
        return std::clamp(static_cast<int>((c[i].*coordinate - lo) * scale), 0, sah_bin_count - 1);
      };
    };
    const SahSplit split = cheapest_sah_split<Bounds>(
        order_.data() + begin, order_.data() + end, [&](int a) { return extent[a] > 0; }, binner_for,
        [&](std::uint32_t i) -> const Bounds& { return bounds[i]; });
    if (split.axis >= 0) {
      mid = static_cast<std::uint32_t>(partition_at(order_.data() + begin, order_.data() + end, split, binner_for) -
                                       order_.data());
      axis = split.axis;
      split_done = mid > begin && mid < end;
    }
  }
  if (!split_done) {
    // Object median on the widest centroid axis (degenerate extents: any order, split by count).
    mid = begin + count / 2;
    std::nth_element(order_.begin() + begin, order_.begin() + mid, order_.begin() + end,
                     [&](std::uint32_t l, std::uint32_t r) { return centroids[l][axis] < centroids[r][axis]; });
  }

  nodes_[index].axis = static_cast<std::uint16_t>(axis);
  build_node(begin, mid, depth + 1, bounds, centroids);  // left child lands at index + 1
  const std::uint32_t right = build_node(mid, end, depth + 1, bounds, centroids);
  nodes_[index].first = right;
  return index;
}

Hit Accelerator::closest_hit(const Ray& ray, double t_min, double t_max) const {
  return nearest<false>(ray, t_min, t_max);
}

Hit Accelerator::closest_shadow_hit(const Ray& ray, double t_min, double t_max) const {
  return nearest<true>(ray, t_min, t_max);
}

template <bool shadow_casters_only>
Hit Accelerator::nearest(const Ray& ray, double t_min, double t_max) const {
  Nearest best{t_max, ~0u, {}};
  for (const std::uint32_t i : unbounded_) consider<shadow_casters_only>(primitives_[i], i, ray, t_min, best);
  const SlabRay slab(ray);
  double t_root = 0;
  if (nodes_.empty() || !slab_hit(nodes_[0].bounds, slab, t_min, best.t, t_root)) return to_hit(best);

  // Subtrees still to visit, with the depth at which the ray enters them (skipped once a nearer hit is known).
  std::uint32_t stack[stack_size];
  double stack_entry[stack_size];
  int top = 0;
  std::uint32_t node = 0;
  for (;;) {
    const Node& n = nodes_[node];
    if (n.count > 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k) {
        const std::uint32_t i = order_[k];
        consider<shadow_casters_only>(primitives_[i], i, ray, t_min, best);
      }
    } else {
      // Near child first: with a negative direction on the split axis the right child is nearer.
      std::uint32_t near_child = node + 1, far_child = n.first;
      if (slab.negative[n.axis]) std::swap(near_child, far_child);
      double t_near = 0, t_far = 0;
      const bool hit_near = slab_hit(nodes_[near_child].bounds, slab, t_min, best.t, t_near);
      const bool hit_far = slab_hit(nodes_[far_child].bounds, slab, t_min, best.t, t_far);
      if (hit_near && hit_far) {
        assert(top < stack_size);
        stack_entry[top] = t_far;
        stack[top++] = far_child;
      }
      if (hit_near || hit_far) {
        node = hit_near ? near_child : far_child;
        continue;
      }
    }
    // Pop the next subtree that may still hold a hit no farther than the best so far (ties need <=).
    do {
      if (top == 0) return to_hit(best);
      --top;
    } while (stack_entry[top] > best.t);
    node = stack[top];
  }
}

void Accelerator::shadow_traverse(const Ray& ray, double t_min, double t_max, ShadowVisitFn visit,
                                  void* context) const {
  // Reports every root in (t_min, t_max) of primitive i; returns false when the visitor asked to stop. The
  // visitor only shades (it never traces), so one buffer per thread serves every call.
  thread_local HitBuffer hits;
  auto report = [&](std::uint32_t i) {
    const Primitive& p = primitives_[i];
    if (!p.casts_shadow || (p.hidden_from & ray.kind)) return true;
    if (!p.data) {   // few roots: no buffer needed
      const Intersections xs = intersect_all(p, ray);
      for (int k = 0; k < xs.count; ++k)
        if (xs.t[k] > t_min && xs.t[k] < t_max && !visit(context, i, SurfaceHit{xs.t[k], &p, xs.element[k], 0, 0}))
          return false;
      return true;
    }
    hits.clear();
    collect_hits(p, ray, hits);
    for (const SurfaceHit& h : hits)
      if (h.t > t_min && h.t < t_max && !visit(context, i, h)) return false;
    return true;
  };
  for (const std::uint32_t i : unbounded_)
    if (!report(i)) return;

  const SlabRay slab(ray);
  double t_entry = 0;
  if (nodes_.empty() || !slab_hit(nodes_[0].bounds, slab, t_min, t_max, t_entry)) return;
  std::uint32_t stack[stack_size];
  int top = 0;
  std::uint32_t node = 0;
  for (;;) {
    const Node& n = nodes_[node];
    if (n.count > 0) {
      for (std::uint32_t k = n.first; k < n.first + n.count; ++k)
        if (!report(order_[k])) return;
    } else {
      // Front to back, so that an opaque occluder near the origin stops the walk early.
      std::uint32_t near_child = node + 1, far_child = n.first;
      if (slab.negative[n.axis]) std::swap(near_child, far_child);
      const bool hit_near = slab_hit(nodes_[near_child].bounds, slab, t_min, t_max, t_entry);
      const bool hit_far = slab_hit(nodes_[far_child].bounds, slab, t_min, t_max, t_entry);
      if (hit_near && hit_far) {
        assert(top < stack_size);
        stack[top++] = far_child;
      }
      if (hit_near || hit_far) {
        node = hit_near ? near_child : far_child;
        continue;
      }
    }
    if (top == 0) return;
    node = stack[--top];
  }
}

std::vector<std::uint32_t> Accelerator::containing_indices(Vec3 point) const {
  std::vector<std::uint32_t> found;
  auto test = [&](std::uint32_t i) {
    if (inside(primitives_[i], point)) found.push_back(i);
  };
  for (const std::uint32_t i : unbounded_) test(i);
  auto holds = [&](const Bounds& b) {
    return point.x >= b.lo.x && point.x <= b.hi.x && point.y >= b.lo.y && point.y <= b.hi.y && point.z >= b.lo.z &&
           point.z <= b.hi.z;
  };
  if (!nodes_.empty() && holds(nodes_[0].bounds)) {
    std::uint32_t stack[stack_size];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
      const Node& n = nodes_[stack[--top]];
      if (n.count > 0) {
        for (std::uint32_t k = n.first; k < n.first + n.count; ++k) test(order_[k]);
        continue;
      }
      const std::uint32_t children[2] = {static_cast<std::uint32_t>(&n - nodes_.data()) + 1, n.first};
      for (const std::uint32_t c : children)
        if (holds(nodes_[c].bounds)) {
          assert(top < stack_size);
          stack[top++] = c;
        }
    }
  }
  std::sort(found.begin(), found.end());
  return found;
}

Hit Accelerator::closest_hit_brute_force(const Ray& ray, double t_min, double t_max) const {
  Nearest best{t_max, ~0u, {}};
  for (std::uint32_t i = 0; i < primitives_.size(); ++i) consider(primitives_[i], i, ray, t_min, best);
  return to_hit(best);
}

}  // namespace povtrace::render

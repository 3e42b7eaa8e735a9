// The shapes whose rays can meet them more often than Intersections holds (superellipsoid, blob, lathe, sor,
// prism, height_field, isosurface): each has roots(), which appends its roots to a RootList, and the templates here
// answer intersect_all, collect_hits and nearest_hit for all of them from that list (shape_registry.hpp picks them
// for every shape with roots()).
#pragma once

#include <algorithm>
#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

// One root: the world depth along the unit world ray, which part of the shape it is on (a height field's
// triangle, the profile segment or end disc of a lathe, prism or sor, the container face of an isosurface; 0 for
// the others) and where on that part
// (the segment parameter w of a lathe or prism; it becomes the SurfaceHit's u).
struct Root {
  double t = 0;
  std::uint32_t element = 0;
  double u = 0;
};
using RootList = std::vector<Root>;

// The thread's root list, emptied: rays allocate only while it is still growing.
inline RootList& root_scratch() {
  thread_local RootList roots;
  roots.clear();
  return roots;
}

// intersect_all: the nearest Intersections::capacity roots, depth-sorted.
template <class Shape>
Intersections first_roots(const Primitive& p, const Ray& ray) {
  RootList& roots = root_scratch();
  Shape::roots(p, ray, roots);
  std::sort(roots.begin(), roots.end(), [](const Root& a, const Root& b) { return a.t < b.t; });
  Intersections out;
  for (const Root& r : roots) {
    if (out.count == Intersections::capacity) break;
    out.t[out.count++] = r.t;
  }
  return out;
}

template <class Shape>
void collect_roots(const Primitive& p, const Ray& ray, HitBuffer& out) {
  RootList& roots = root_scratch();
  Shape::roots(p, ray, roots);
  for (const Root& r : roots) out.push_back(SurfaceHit{r.t, &p, r.element, r.u, 0});
}

template <class Shape>
std::optional<SurfaceHit> nearest_root(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  RootList& roots = root_scratch();
  Shape::roots(p, ray, roots);
  std::optional<SurfaceHit> nearest;
  for (const Root& r : roots) {
    if (!(r.t > t_min) || !(r.t < t_max)) continue;
    if (nearest && !(r.t < nearest->t)) continue;
    nearest = SurfaceHit{r.t, &p, r.element, r.u, 0};
  }
  return nearest;
}

}  // namespace povtrace::render::shapes

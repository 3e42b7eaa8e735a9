// intersect_all, collect_hits and nearest_hit for the shapes with many roots (many_roots.hpp), from their root
// lists. nearest_hit gathers into a per-thread list so that rays allocate only while that list is still growing.
#include "renderer/shapes/many_roots.hpp"

#include <algorithm>

namespace povtrace::render::shapes {

bool has_many_roots(ShapeType type) {
  return type == ShapeType::superellipsoid || type == ShapeType::height_field || type == ShapeType::blob ||
         type == ShapeType::lathe || type == ShapeType::prism || type == ShapeType::sor ||
         type == ShapeType::isosurface;
}

void append_roots(const Primitive& p, const Ray& ray, RootList& out) {
  switch (p.type) {
    case ShapeType::superellipsoid: superellipsoid_roots(p, ray, out); return;
    case ShapeType::height_field: height_field_roots(p, ray, out); return;
    case ShapeType::blob: blob_roots(p, ray, out); return;
    case ShapeType::lathe: lathe_roots(p, ray, out); return;
    case ShapeType::prism: prism_roots(p, ray, out); return;
    case ShapeType::sor: sor_roots(p, ray, out); return;
    case ShapeType::isosurface: isosurface_roots(p, ray, out); return;
    default: return;
  }
}

namespace {
RootList& scratch() {
  thread_local RootList roots;
  roots.clear();
  return roots;
}
}  // namespace

Intersections first_roots(const Primitive& p, const Ray& ray) {
  RootList& roots = scratch();
  append_roots(p, ray, roots);
  std::sort(roots.begin(), roots.end(), [](const Root& a, const Root& b) { return a.t < b.t; });
  Intersections out;
  for (const Root& r : roots) {
    if (out.count == Intersections::capacity) break;
    out.t[out.count++] = r.t;
  }
  return out;
}

void collect_many_roots(const Primitive& p, const Ray& ray, HitBuffer& out) {
  RootList& roots = scratch();
  append_roots(p, ray, roots);
  for (const Root& r : roots) out.push_back(SurfaceHit{r.t, &p, r.element, r.u, 0});
}

bool nearest_of_many_roots(const Primitive& p, const Ray& ray, double t_min, double t_max, SurfaceHit& hit) {
  RootList& roots = scratch();
  append_roots(p, ray, roots);
  bool found = false;
  for (const Root& r : roots) {
    if (!(r.t > t_min) || !(r.t < t_max)) continue;
    if (found && !(r.t < hit.t)) continue;
    hit = SurfaceHit{r.t, &p, r.element, r.u, 0};
    found = true;
  }
  return found;
}

}  // namespace povtrace::render::shapes

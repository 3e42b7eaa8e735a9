// Surface of revolution.
//
// SDL: `sor { N, <r, y>… [open] [sturm] object_modifiers… }` (POV-Ray 3.7 reference "Surface of Revolution"): the
// radius squared a cubic in the height between consecutive points, turned about the y axis, closed by discs at both
// ends unless `open`. Primitive: data = SorData (sweep_build.cpp).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/sor.cpp, 3.7-stable):
// - The ray goes to sor space with its direction normalised (length L). It misses when it heads away from the
//   heights or the x range, or when P×D's y component over |D's xz part| (signed, as POV-Ray leaves it) exceeds the
//   largest radius.
// - Closed, and |Dy| > 1e-10: each end disc whose squared radius exceeds 1e-4 is hit where the ray meets its plane
//   within that squared radius.
// - Each segment whose bounding ring the ray reaches (bounding_rings.cpp) is met where (Px + t·Dx)² + (Pz + t·Dz)²
//   = r²(Py + t·Dy), a cubic in t (Solve_Polynomial: Sturm sequences with `sturm`, else the closed form without
//   polishing, whose roots for nearly level rays — leading coefficient a·Dy³ just above 1e-10 — are far off: the
//   noisy band POV-Ray draws along a sor's horizon without `sturm`), at heights within the segment's. Hits count
//   at world depths t/L in (1e-4, MAX_DISTANCE).
// - Inside: within the heights and the largest radius, the first segment whose heights hold the point decides:
//   inside when x² + z² ≤ r²(y).
// - Normal: (Px, −r²'(Py)/2, Pz) on a segment, (0, −1, 0) on the lower disc, (0, 1, 0) on the upper one.
// - Bounds: x and z in [−R, R] with R the largest radius, y in the heights.
#include <algorithm>
#include <cmath>

#include "renderer/shapes/many_roots.hpp"
#include "runtime/polynomial_roots.hpp"
#include "renderer/shapes/sweep.hpp"
#include "renderer/shapes/sor.hpp"
#include "renderer/shapes/uv_helpers.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-4;   // sor.cpp DEPTH_TOLERANCE

const SorData& data_of(const Primitive& p) { return static_cast<const SorData&>(*p.data); }

void push_hit(double depth, std::uint32_t element, RootList& out) {
  if (depth > depth_tolerance && depth < tolerance::max_distance) out.push_back(Root{depth, element, 0.0});
}

// The end discs: the plane y = h within squared radius r2.
void disc_hits(const SorData& d, Vec3 p, Vec3 v, double len, RootList& out) {
  if (!d.closed || !(std::fabs(v.y) > tolerance::epsilon)) return;
  const struct { double h, r2; std::uint32_t element; } discs[2] = {{d.height1, d.base_radius2, base_element},
                                                                     {d.height2, d.cap_radius2, cap_element}};
  for (const auto& disc : discs) {
    if (!(disc.r2 > depth_tolerance)) continue;
    const double t = (disc.h - p.y) / v.y;
    const double u = p.x + t * v.x, w = p.z + t * v.z;
    if (u * u + w * w <= disc.r2) push_hit(t / len, disc.element, out);
  }
}

// The segment's cubic in t, highest power first.
std::array<double, 4> segment_cubic(const SorSegment& s, Vec3 p, Vec3 v) {
  const double radial = v.x * v.x + v.z * v.z;
  return {s.a * v.y * v.y * v.y, v.y * v.y * (3.0 * s.a * p.y + s.b) - radial,
          v.y * (p.y * (3.0 * s.a * p.y + 2.0 * s.b) + s.c) - 2.0 * (p.x * v.x + p.z * v.z),
          radius_squared(s, p.y) - p.x * p.x - p.z * p.z};
}
// The first segment whose heights hold y (POV-Ray's inside rule), or the segment count.
std::uint32_t sor_segment_at(const SorData& d, double y) {
  std::uint32_t k = 0;
  while (k < d.segments.size() && !(y >= d.rings[k].h1 && y <= d.rings[k].h2)) ++k;
  return k;
}
}  // namespace

void SorShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const SorData& d = data_of(p);
  const LocalRay r = local_ray(p, ray);
  const Vec3 q = r.p, v = r.d;
  const double len = r.len;
  if ((v.y >= 0.0 && q.y > d.height2) || (v.y <= 0.0 && q.y < d.height1) || (v.x >= 0.0 && q.x > d.radius2) ||
      (v.x <= 0.0 && q.x < -d.radius2))
    return;
  double r0 = q.x * v.z - q.z * v.x;
  if (const double a = v.x * v.x + v.z * v.z; a > 0.0) r0 /= std::sqrt(a);
  if (r0 > d.radius2) return;
  disc_hits(d, q, v, len, out);
  for (std::uint32_t k = 0; k < d.segments.size(); ++k) {
    if (!ring_reached(d.rings[k], q, v)) continue;
    const auto c = segment_cubic(d.segments[k], q, v);
    double t[3];
    const int n = poly::solve_polynomial(3, c.data(), t, d.sturm, 0.0, tolerance::max_distance);
    for (int j = 0; j < n; ++j) {
      const double h = q.y + t[j] * v.y;
      if (h >= d.rings[k].h1 && h <= d.rings[k].h2) push_hit(t[j] / len, k, out);
    }
  }
}

Vec3 SorShape::normal_at(const Primitive& p, std::uint32_t element, Vec3 world_point) {
  const SorData& d = data_of(p);
  Vec3 n{0, element == base_element ? -1.0 : 1.0, 0};
  if (element != base_element && element != cap_element) {
    const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
    const SorSegment& s = d.segments[element];
    n = Vec3{q.x, -0.5 * (q.y * (3.0 * s.a * q.y + 2.0 * s.b) + s.c), q.z};
  }
  if (p.transformed) n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / length(n));
}

// The normal at a point without its hit: an end disc when the point is nearer its plane than the curve.
Vec3 SorShape::normal(const Primitive& p, Vec3 world_point) {
  const SorData& d = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const double r2 = q.x * q.x + q.z * q.z;
  const auto last = static_cast<std::uint32_t>(d.segments.size() - 1);
  std::uint32_t element = std::min(sor_segment_at(d, q.y), last);
  double best = std::fabs(std::sqrt(std::max(0.0, radius_squared(d.segments[element], q.y))) - std::sqrt(r2));
  if (d.closed && r2 <= d.base_radius2 && std::fabs(q.y - d.height1) < best) {
    best = std::fabs(q.y - d.height1);
    element = base_element;
  }
  if (d.closed && r2 <= d.cap_radius2 && std::fabs(q.y - d.height2) < best) element = cap_element;
  return normal_at(p, element, world_point);
}

bool SorShape::inside(const Primitive& p, Vec3 world_point) {
  const SorData& d = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  bool in = false;
  if (q.y >= d.height1 && q.y <= d.height2) {
    const double r2 = q.x * q.x + q.z * q.z;
    const std::uint32_t k = sor_segment_at(d, q.y);
    in = r2 <= d.radius2 * d.radius2 && k < d.segments.size() && r2 <= radius_squared(d.segments[k], q.y);
  }
  return in != p.inverse;
}

Bounds SorShape::object_bounds(const Primitive& p) {
  const SorData& d = data_of(p);
  return Bounds{{-d.radius2, d.height1, -d.radius2}, {d.radius2, d.height2, d.radius2}};
}

// A sor: u around y; v the height within the segment's ring, over the number of segments; on the base disc it runs
// from −1 at the axis to 0 at the rim, on the cap from 2 to 1 (POV-Ray's Sor::UVCoord).
std::array<double, 2> SorShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  using uv_helpers::object_point;
  using uv_helpers::turn_around_y;
  const auto& d = static_cast<const SorData&>(*hit.leaf->data);
  const Vec3 q = object_point(*hit.leaf, world_point);
  const double u = turn_around_y(q);
  const double r = std::sqrt(q.x * q.x + q.z * q.z);
  if (hit.element == base_element) return {u, r / std::sqrt(d.base_radius2) - 1.0};
  if (hit.element == cap_element) return {u, 2.0 - r / std::sqrt(d.cap_radius2)};
  const Ring& ring = d.rings[hit.element];
  const double per_segment = 1.0 / double(d.segments.size());
  return {u, (q.y - ring.h1) / (ring.h2 - ring.h1) * per_segment + double(hit.element) * per_segment};
}

}  // namespace povtrace::render::shapes

// Prism.
//
// SDL: `prism { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] [linear_sweep | conic_sweep]
// H1, H2, N, <x, z>… [open] [sturm] object_modifiers… }` (POV-Ray 3.7 reference "Prism"): a 2-D outline in the x-z
// plane swept along y from H1 to H2, straight (linear_sweep) or scaled by y as a cone from the origin (conic_sweep),
// closed by its outline at both heights unless `open`. Primitive: data = PrismData (sweep_build.cpp).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/prism.cpp, 3.7-stable):
// - A prism whose outline does not close (parser) is never hit. The ray goes to prism space with its direction
//   normalised (length L); it misses when it heads away from the outline's x or z range.
// - |Dy| < 1e-10: a ray outside the heights misses. Otherwise, when closed, the upper then the lower plane is hit at
//   parameter k (more than 1e-4) where the point there (divided by the height for a conic sweep, skipped when that
//   height is within 1e-10 of 0) lies inside the outline.
// - When |Dx| or |Dz| exceeds 1e-10, every segment whose rectangle the ray does not head away from is met where the
//   outline's cubic crosses the ray's plane (linear sweep: the vertical plane through the ray; conic: the plane
//   through the ray and the origin): linearly (skipped when the slope is within 1e-10 of 0), as a quadratic, or as
//   a cubic (Sturm sequences with `sturm`; a linear sweep first tests the ray against the rectangle). A root w in
//   [0, 1] gives the ray parameter from x (or from z when |Dx| ≤ 1e-10; for a conic sweep from the x or z
//   equation whose denominator exceeds 1e-10) and counts when the height there lies in [H1, H2].
// - Every hit counts at world depth k/L in (1e-4, MAX_DISTANCE).
// - Inside the outline (POV-Ray's in_curve): within the outline's rectangle, count the segments whose z range holds
//   v and whose largest x is at least u where z(w) = v for w in [0, 1] with x(w) ≥ u; odd is inside.
// - Inside the prism: H1 ≤ y < H2 and (x, z) — divided by y for a conic sweep, outside when |y| ≤ 1e-10 — inside
//   the outline (open or not).
// - Normal: on a segment (z'(w), 0, −x'(w)), for a conic sweep with y = −(Px·Nx + Pz·Nz)/Py (when |Py| > 1e-10,
//   else (0, 1, 0)); (0, 1, 0) on both end planes.
// - Bounds: the outline's rectangle (scaled over the heights for a conic sweep) between the heights.
#include <algorithm>
#include <cmath>

#include "renderer/shapes/many_roots.hpp"
#include "runtime/polynomial_roots.hpp"
#include "renderer/shapes/sweep.hpp"
#include "renderer/shapes/prism.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-4;   // prism.cpp DEPTH_TOLERANCE
constexpr double eps = tolerance::epsilon;

const PrismData& data_of(const Primitive& p) { return static_cast<const PrismData&>(*p.data); }

// Whether the ray heads away from the rectangle [x1, x2] × [z1, z2] (POV-Ray's modified Cohen-Sutherland test).
bool heads_away(const LocalRay& r, double x1, double x2, double z1, double z2) {
  return (r.d.x >= 0.0 && r.p.x > x2) || (r.d.x <= 0.0 && r.p.x < x1) || (r.d.z >= 0.0 && r.p.z > z2) ||
         (r.d.z <= 0.0 && r.p.z < z1);
}

// The 2-D ray (x, z) meets the rectangle ahead (a slab test; depths below 1e-10 count as behind).
bool meets_rectangle(const LocalRay& r, const PrismSegment& s) {
  double near = -tolerance::bound_huge, far = tolerance::bound_huge;
  const double o[2] = {r.p.x, r.p.z}, v[2] = {r.d.x, r.d.z}, lo[2] = {s.x1, s.z1}, hi[2] = {s.x2, s.z2};
  for (int axis = 0; axis < 2; ++axis) {
    if (std::fabs(v[axis]) > eps) {
      double t1 = (lo[axis] - o[axis]) / v[axis], t2 = (hi[axis] - o[axis]) / v[axis];
      if (v[axis] < 0.0) std::swap(t1, t2);
      near = std::max(near, t1), far = std::min(far, t2);
    } else if (o[axis] < lo[axis] || o[axis] > hi[axis]) {
      return false;
    }
  }
  return !(far < eps || near > far);
}

void push_hit(double k, double len, std::uint32_t element, double w, RootList& out) {
  const double depth = k / len;
  if (depth > depth_tolerance && depth < tolerance::max_distance) out.push_back(Root{depth, element, w});
}

// POV-Ray's in_curve (see the top of this file).
bool prism_outline_holds(const PrismData& d, double u, double v) {
  if (!(u >= d.u1 && u <= d.u2 && v >= d.v1 && v <= d.v2)) return false;
  int crossings = 0;
  for (const PrismSegment& s : d.segments) {
    if (!(v >= s.v1 && v <= s.v2 && u <= s.u2)) continue;
    const Cubic& z = s.curve.y;
    const double c[4] = {z[0], z[1], z[2], z[3] - v};
    double w[3];
    const int n = poly::solve_polynomial(3, c, w, d.sturm, 0.0, tolerance::max_distance);
    for (int j = 0; j < n; ++j)
      if (w[j] >= 0.0 && w[j] <= 1.0 && evaluate(s.curve.x, w[j]) - u >= 0.0) ++crossings;
  }
  return crossings % 2 == 1;
}

// The end planes of a closed prism, upper first.
void end_plane_hits(const PrismData& d, const LocalRay& r, RootList& out) {
  const struct { double h; std::uint32_t element; } planes[2] = {{d.height2, cap_element}, {d.height1, base_element}};
  for (const auto& plane : planes) {
    if (d.conic && !(std::fabs(plane.h) > eps)) continue;
    const double k = (plane.h - r.p.y) / r.d.y;
    if (!(k > depth_tolerance && k < tolerance::max_distance)) continue;
    const double scale = d.conic ? plane.h : 1.0;
    if (prism_outline_holds(d, (r.p.x + k * r.d.x) / scale, (r.p.z + k * r.d.z) / scale))
      push_hit(k, r.len, plane.element, 0.0, out);
  }
}

// Where the segment's outline crosses the ray's plane: a cubic in w (highest power first; lower degrees lead with
// zeros). Linear sweep: the vertical plane through the ray; conic: the plane through the ray and the origin.
std::array<double, 4> crossing_cubic(const PrismData& d, const ProfileSegment& s, const LocalRay& r) {
  std::array<double, 4> c{};
  if (!d.conic) {
    for (int k = 0; k < 3; ++k) c[k] = s.x[k] * r.d.z - s.y[k] * r.d.x;
    c[3] = r.d.z * (s.x[3] - r.p.x) - r.d.x * (s.y[3] - r.p.z);
    return c;
  }
  const double k1 = r.p.z * r.d.y - r.p.y * r.d.z, k2 = r.p.y * r.d.x - r.p.x * r.d.y,
               k3 = r.p.x * r.d.z - r.p.z * r.d.x;
  for (int k = 0; k < 4; ++k) c[k] = s.x[k] * k1 + s.y[k] * k2;
  c[3] += k3;
  return c;
}

// The roots w of the segment's crossing polynomial, by spline kind as POV-Ray solves them.
int crossing_roots(const PrismData& d, const PrismSegment& s, const LocalRay& r, double w[3]) {
  if (d.spline != SplineKind::linear && d.spline != SplineKind::quadratic && !d.conic && !meets_rectangle(r, s))
    return 0;
  const auto c = crossing_cubic(d, s.curve, r);
  switch (d.spline) {
    case SplineKind::linear:
      if (!(std::fabs(c[2]) > eps)) return 0;
      w[0] = -c[3] / c[2];
      return 1;
    case SplineKind::quadratic: return poly::solve_polynomial(2, c.data() + 1, w, false, 0.0, tolerance::max_distance);
    default: return poly::solve_polynomial(3, c.data(), w, d.sturm, 0.0, tolerance::max_distance);
  }
}

// The ray parameter where it meets the outline's point w (false when POV-Ray finds no denominator to use).
bool ray_parameter(const PrismData& d, const ProfileSegment& s, double w, const LocalRay& r, double& k) {
  const double x = evaluate(s.x, w);
  if (!d.conic) {
    k = std::fabs(r.d.x) > eps ? (x - r.p.x) / r.d.x : (evaluate(s.y, w) - r.p.z) / r.d.z;
    return true;
  }
  if (const double h = r.d.x - x * r.d.y; std::fabs(h) > eps) {
    k = (x * r.p.y - r.p.x) / h;
    return true;
  }
  const double z = evaluate(s.y, w);
  const double h = r.d.z - z * r.d.y;
  if (!(std::fabs(h) > eps)) return false;
  k = (z * r.p.y - r.p.z) / h;
  return true;
}

void segment_hits(const PrismData& d, std::uint32_t index, const LocalRay& r, RootList& out) {
  const PrismSegment& s = d.segments[index];
  if (heads_away(r, s.x1, s.x2, s.z1, s.z2)) return;
  double w[3];
  const int n = crossing_roots(d, s, r, w);
  for (int j = 0; j < n; ++j) {
    double k = 0;
    if (!(w[j] >= 0.0 && w[j] <= 1.0) || !ray_parameter(d, s.curve, w[j], r, k)) continue;
    const double h = r.p.y + k * r.d.y;
    if (h >= d.height1 && h <= d.height2) push_hit(k, r.len, index, w[j], out);
  }
}
}  // namespace

void PrismShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const PrismData& d = data_of(p);
  if (d.degenerate) return;
  const LocalRay r = local_ray(p, ray);
  if (heads_away(r, d.x1, d.x2, d.z1, d.z2)) return;
  if (std::fabs(r.d.y) < eps) {
    if (r.p.y < d.height1 || r.p.y > d.height2) return;
  } else if (d.closed) {
    end_plane_hits(d, r, out);
  }
  if (!(std::fabs(r.d.x) > eps) && !(std::fabs(r.d.z) > eps)) return;
  for (std::uint32_t k = 0; k < d.segments.size(); ++k) segment_hits(d, k, r, out);
}

Vec3 PrismShape::normal_at(const Primitive& p, std::uint32_t element, double w, Vec3 world_point) {
  const PrismData& d = data_of(p);
  Vec3 n{0, 1, 0};
  if (element != base_element && element != cap_element) {
    const ProfileSegment& s = d.segments[element].curve;
    const double nx = derivative(s.y, w), nz = -derivative(s.x, w);
    if (!d.conic) {
      n = Vec3{nx, 0.0, nz};
    } else {
      const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
      if (std::fabs(q.y) > eps) n = Vec3{nx, -(q.x * nx + q.z * nz) / q.y, nz};
    }
  }
  if (p.transformed) n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / length(n));
}

// The normal at a point without its hit: an end plane when the point is nearer it than the outline.
Vec3 PrismShape::normal(const Primitive& p, Vec3 world_point) {
  const PrismData& d = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const double scale = d.conic && std::fabs(q.y) > eps ? q.y : 1.0;
  std::uint32_t element = cap_element;
  ProfileSpot best;
  for (std::uint32_t k = 0; k < d.segments.size(); ++k)
    if (const ProfileSpot s = nearest_spot(d.segments[k].curve, q.x / scale, q.z / scale, false);
        s.distance < best.distance)
      best = s, element = k;
  const double plane = std::min(std::fabs(q.y - d.height1), std::fabs(q.y - d.height2));
  if (d.closed && plane < best.distance * std::fabs(scale)) element = cap_element;
  return normal_at(p, element, best.w, world_point);
}

bool PrismShape::inside(const Primitive& p, Vec3 world_point) {
  const PrismData& d = data_of(p);
  Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  bool in = false;
  if (q.y >= d.height1 && q.y < d.height2) {
    if (d.conic) {
      const bool off_apex = std::fabs(q.y) > eps;
      q.x = off_apex ? q.x / q.y : HUGE_VAL;
      q.z = off_apex ? q.z / q.y : HUGE_VAL;
    }
    in = prism_outline_holds(d, q.x, q.z);
  }
  return in != p.inverse;
}

Bounds PrismShape::object_bounds(const Primitive& p) {
  const PrismData& d = data_of(p);
  if (d.segments.empty()) return {};
  return Bounds{{d.x1, d.height1, d.z1}, {d.x2, d.height2, d.z2}};
}

}  // namespace povtrace::render::shapes

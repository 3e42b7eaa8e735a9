// Lathe.
//
// SDL: `lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] N, <x, y>… [sturm]
// object_modifiers… }` (POV-Ray 3.7 reference "Lathe"): the 2-D spline turned about the y axis (x is the radius).
// Primitive: data = LatheData (sweep_build.cpp).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/lathe.cpp, 3.7-stable):
// - The ray goes to lathe space with its direction normalised (length L). It misses when it heads away from the
//   profile's height or x range, or passes farther than the largest x from the axis; otherwise each segment whose
//   bounding ring it reaches (bounding_rings.cpp) is tested.
// - A segment (x(w), y(w)) is met where x(w)²·Dy² = (Px·Dy + (y(w) − Py)·Dx)² + (Pz·Dy + (y(w) − Py)·Dz)²: degree 2,
//   4 or 6 in w for linear, quadratic and cubic/Bézier splines, solved by POV-Ray's Solve_Polynomial (no order
//   reduction; Sturm sequences for degree 6, and for degree 4 with `sturm`). Roots w in [0, 1] are hits at depth
//   (y(w) − Py)/(Dy·L); when |Dy| ≤ 1e-10 the depth comes instead from the quadratic in the ray parameter where the
//   ray's distance from the axis equals |x(w)|. Hits count at world depths in (1e-4, MAX_DISTANCE).
// - Inside: within the profile's heights and x range, counting the segments (heights widened by 1e-10) where
//   y(w) = Py for w in [0, 1] with x(w) ≥ the point's distance from the axis; an odd count is inside.
// - Normal: (y'(w)·Px, −x'(w)·r, y'(w)·Pz) with r the distance from the axis, or (0, 1, 0) on the axis (r² ≤ 1e-10).
// - Bounds: x in [−X, X], z likewise, y in the profile's heights, X the largest x.
#include <algorithm>
#include <cmath>

#include "renderer/shapes/many_roots.hpp"
#include "runtime/polynomial_roots.hpp"
#include "renderer/shapes/sweep.hpp"
#include "renderer/shapes/lathe.hpp"
#include "renderer/shapes/uv_helpers.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double depth_tolerance = 1e-4;   // lathe.cpp DEPTH_TOLERANCE

const LatheData& data_of(const Primitive& p) { return static_cast<const LatheData&>(*p.data); }

// a·b for cubics as the sextic product (highest power first).
std::array<double, 7> product(const Cubic& a, const Cubic& b) {
  std::array<double, 7> out{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) out[i + j] += a[i] * b[j];
  return out;
}

// The polynomial in w above: r·u² + 2·Dy·m·u + Dy²·(Px² + Pz²) − Dy²·x², with u = y − Py, r = Dx² + Dz²,
// m = Dx·Px + Dz·Pz.
std::array<double, 7> segment_polynomial(const ProfileSegment& s, const LocalRay& r) {
  Cubic u = s.y;
  u[3] -= r.p.y;
  const double radial = r.d.x * r.d.x + r.d.z * r.d.z, m = r.d.x * r.p.x + r.d.z * r.p.z, dy2 = r.d.y * r.d.y;
  const auto uu = product(u, u), xx = product(s.x, s.x);
  std::array<double, 7> c{};
  for (int k = 0; k < 7; ++k) c[k] = radial * uu[k] - dy2 * xx[k];
  for (int k = 0; k < 4; ++k) c[k + 3] += 2.0 * r.d.y * m * u[k];
  c[6] += dy2 * (r.p.x * r.p.x + r.p.z * r.p.z);
  return c;
}

void push_hit(double depth, std::uint32_t segment, double w, RootList& out) {
  if (depth > depth_tolerance && depth < tolerance::max_distance) out.push_back(Root{depth, segment, w});
}

// The hits of one root w of segment k.
void hits_at(const LatheData& d, std::uint32_t k, double w, const LocalRay& r, RootList& out) {
  const ProfileSegment& s = d.segments[k];
  if (std::fabs(r.d.y) > tolerance::epsilon) {
    push_hit((evaluate(s.y, w) - r.p.y) / (r.d.y * r.len), k, w, out);
    return;
  }
  const double x = evaluate(s.x, w);
  const double q[3] = {r.d.x * r.d.x + r.d.z * r.d.z, 2.0 * (r.d.x * r.p.x + r.d.z * r.p.z),
                       r.p.x * r.p.x + r.p.z * r.p.z - x * x};
  double t[2];
  const int n = poly::solve_polynomial(2, q, t, false, 0.0, tolerance::max_distance);
  for (int j = 0; j < n; ++j) push_hit(t[j] / r.len, k, w, out);
}

bool misses_bounds(const LatheData& d, const LocalRay& r) {
  const Vec3 p = r.p, v = r.d;
  if ((v.y >= 0.0 && p.y > d.height2) || (v.y <= 0.0 && p.y < d.height1) || (v.x >= 0.0 && p.x > d.radius2) ||
      (v.x <= 0.0 && p.x < -d.radius2))
    return true;
  double r0 = std::fabs(p.x * v.z - p.z * v.x);
  const double a = v.x * v.x + v.z * v.z;
  if (a > 0.0) r0 /= std::sqrt(a);
  return r0 > d.radius2;
}

int degree_of(SplineKind s) { return s == SplineKind::linear ? 2 : s == SplineKind::quadratic ? 4 : 6; }
}  // namespace

void LatheShape::roots(const Primitive& p, const Ray& ray, RootList& out) {
  const LatheData& d = data_of(p);
  const LocalRay r = local_ray(p, ray);
  if (d.segments.empty() || misses_bounds(d, r)) return;
  const int degree = degree_of(d.spline);
  const bool sturm = d.sturm && d.spline != SplineKind::linear;
  for (std::uint32_t k = 0; k < d.segments.size(); ++k) {
    if (!ring_reached(d.rings[k], r.p, r.d)) continue;
    const auto c = segment_polynomial(d.segments[k], r);
    double w[6];
    const int n = poly::solve_polynomial(degree, c.data() + (6 - degree), w, sturm, 0.0, tolerance::max_distance);
    for (int j = 0; j < n; ++j)
      if (w[j] >= 0.0 && w[j] <= 1.0) hits_at(d, k, w[j], r, out);
  }
}

Vec3 LatheShape::normal_at(const Primitive& p, std::uint32_t segment, double w, Vec3 world_point) {
  const ProfileSegment& s = data_of(p).segments[segment];
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  Vec3 n{0, 1, 0};
  const double r2 = q.x * q.x + q.z * q.z;
  if (r2 > tolerance::epsilon) {
    const double r = std::sqrt(r2), dx = derivative(s.x, w), dy = derivative(s.y, w);
    n = Vec3{dy * q.x, -dx * r, dy * q.z};
  }
  if (p.transformed) n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / length(n));
}

// The normal at a point without its hit: the segment point nearest in the profile plane decides.
Vec3 LatheShape::normal(const Primitive& p, Vec3 world_point) {
  const LatheData& d = data_of(p);
  if (d.segments.empty()) return {0, 1, 0};
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const double r = std::sqrt(q.x * q.x + q.z * q.z);
  std::uint32_t segment = 0;
  ProfileSpot best;
  for (std::uint32_t k = 0; k < d.segments.size(); ++k)
    if (const ProfileSpot s = nearest_spot(d.segments[k], r, q.y, true); s.distance < best.distance)
      best = s, segment = k;
  return normal_at(p, segment, best.w, world_point);
}

bool LatheShape::inside(const Primitive& p, Vec3 world_point) {
  const LatheData& d = data_of(p);
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  int crossings = 0;
  const double r = std::sqrt(q.x * q.x + q.z * q.z);
  if (q.y >= d.height1 && q.y <= d.height2 && r >= d.radius1 && r <= d.radius2) {
    for (std::size_t k = 0; k < d.segments.size(); ++k) {
      if (q.y < d.rings[k].h1 - tolerance::epsilon || q.y > d.rings[k].h2 + tolerance::epsilon) continue;
      const Cubic& y = d.segments[k].y;
      const double c[4] = {y[0], y[1], y[2], y[3] - q.y};
      double w[3];
      const int n = poly::solve_polynomial(3, c, w, d.sturm, 0.0, tolerance::max_distance);
      for (int j = 0; j < n; ++j)
        if (w[j] >= 0.0 && w[j] <= 1.0 && evaluate(d.segments[k].x, w[j]) - r >= 0.0) ++crossings;
    }
  }
  return (crossings % 2 == 1) != p.inverse;
}

Bounds LatheShape::object_bounds(const Primitive& p) {
  const LatheData& d = data_of(p);
  if (d.segments.empty()) return {};
  return Bounds{{-d.radius2, d.height1, -d.radius2}, {d.radius2, d.height2, d.radius2}};
}

// uv for uv_mapping as POV-Ray's Lathe::UVCoord (lathe.cpp): u around y as the sphere's, v the segment index plus
// the segment parameter w, over the number of segments (at most 1).
std::array<double, 2> LatheShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  using uv_helpers::object_point;
  using uv_helpers::turn_around_y;
  const auto& d = static_cast<const LatheData&>(*hit.leaf->data);
  const double v = (hit.u + double(hit.element)) / double(d.segments.size());
  return {turn_around_y(object_point(*hit.leaf, world_point)), std::min(v, 1.0)};
}

}  // namespace povtrace::render::shapes

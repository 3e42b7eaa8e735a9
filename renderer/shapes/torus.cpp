// Torus.
//
// SDL: `torus { Major, Minor [sturm]  object_modifiers... }` (POV-Ray 3.7 reference "Torus"): the tube of radius
// Minor around the circle of radius Major in the XZ plane, centred at the origin, around +y.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/torus.cpp, 3.7-stable):
// - The world ray goes to object space, direction normalised (length L).
// - A bounding test first: the "thick cylinder" between radii max(R − r, 0) and R + r and heights ±r. The ray
//   must meet one of its four surfaces at a canonical depth in (EPSILON, MAX_DISTANCE): the top and bottom annuli
//   (skipped when |Dy| < EPSILON, where an origin outside the slab |y| <= r misses at once), then the outer and the
//   inner cylinder (when Dx² + Dz² > EPSILON).
// - Precision from afar: when the origin is farther from the centre than R + 2r, it is first moved along the ray
//   to that distance (Closer = |P| − (R + 2r)); the quartic is solved there, so its coefficients stay of the size
//   of the torus, and Closer is added back to every root. A torus seen from 1e5 away is then as exact as one seen
//   from nearby.
// - The quartic in the depth t for the unit direction, with k1 = |P|² − R² − r², k2 = P·D:
//   t⁴ + 4k2 t³ + 2(k1 + 2(k2² + R² Dy²)) t² + 4(k2 k1 + 2R² Py Dy) t + k1² + 4R²(Py² − r²) = 0,
//   solved by Solve_Polynomial with ROOT_TOLERANCE 1e-4 (the t ≈ 0 root of a ray starting on the surface is
//   removed) and Sturm sequences with `sturm` (polynomial_roots.cpp has the rules).
// - A root is kept when its *world* depth (t + Closer) / L lies in (1e-4, MAX_DISTANCE).
// - Inside: (√(x² + z²) − R)² + y² <= r² — the surface counts as inside; `inverse` negates the test.
// - Normal: P − R·(x, 0, z)/√(x² + z²) (just P on the axis, within EPSILON), carried to world by the inverse
//   transpose and normalised.
// - Bounds: [−(R + r), R + r] × [−r, r] × [−(R + r), R + r] carried to world.
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/insert_sorted.hpp"
#include "runtime/polynomial_roots.hpp"
#include "renderer/shapes/torus.hpp"
#include "renderer/shapes/uv_helpers.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double torus_depth = 1e-4;      // torus.cpp DEPTH_TOLERANCE
constexpr double root_tolerance = 1e-4;   // torus.cpp ROOT_TOLERANCE: order reduction for a root at t ≈ 0

bool within_ray(double k) { return k > tolerance::epsilon && k < tolerance::max_distance; }

// Whether the ray meets the annulus r_in² <= x² + z² <= r_out² of the plane y = h.
bool meets_annulus(Vec3 o, Vec3 d, double h, double r_in2, double r_out2) {
  const double k = (h - o.y) / d.y;
  if (!within_ray(k)) return false;
  const double u = o.x + k * d.x, v = o.z + k * d.z;
  const double r = u * u + v * v;
  return r >= r_in2 && r <= r_out2;
}

// Whether the ray meets the cylinder x² + z² = radius2 between the heights lo and hi.
bool meets_cylinder(Vec3 o, Vec3 d, double a, double b, double radius2, double lo, double hi) {
  const double c = o.x * o.x + o.z * o.z - radius2;
  double disc = b * b - a * c;
  if (disc < 0.0) return false;
  disc = std::sqrt(disc);
  for (const double k : {(-b + disc) / a, (-b - disc) / a}) {
    if (!within_ray(k)) continue;
    const double h = o.y + k * d.y;
    if (h >= lo && h <= hi) return true;
  }
  return false;
}

// The thick cylinder around the torus (its bounding test).
bool meets_thick_cylinder(Vec3 o, Vec3 d, double h, double r_in2, double r_out2) {
  if (std::abs(d.y) < tolerance::epsilon) {
    if (o.y < -h || o.y > h) return false;
  } else if (meets_annulus(o, d, h, r_in2, r_out2) || meets_annulus(o, d, -h, r_in2, r_out2)) {
    return true;
  }
  const double a = d.x * d.x + d.z * d.z;
  if (!(a > tolerance::epsilon)) return false;
  const double b = o.x * d.x + o.z * d.z;
  return meets_cylinder(o, d, a, b, r_out2, -h, h) || meets_cylinder(o, d, a, b, r_in2, -h, h);
}
}  // namespace

Intersections TorusShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const double major = p.a.x, minor = p.a.y;
  Vec3 o = p.transformed ? p.object_from_world.point(ray.origin) : ray.origin;
  Vec3 d = p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction;
  const double len = std::sqrt(dot(d, d));
  d *= 1.0 / len;
  const double r_in = major < minor ? 0.0 : (major - minor) * (major - minor);
  const double r_out = (major + minor) * (major + minor);
  if (!meets_thick_cylinder(o, d, minor, r_in, r_out)) return out;
  // Move a far origin to the sphere of radius R + 2r (see the header): precision of the quartic's coefficients.
  const double safe_radius = major + 2.0 * minor;
  double closer = 0.0;
  if (const double o2 = dot(o, o); o2 > safe_radius * safe_radius) {
    closer = std::sqrt(o2) - safe_radius;
    o = o + d * closer;
  }
  const double R2 = major * major, r2 = minor * minor;
  const double k1 = dot(o, o) - R2 - r2;
  const double k2 = dot(o, d);
  const double c[5] = {1.0, 4.0 * k2, 2.0 * (k1 + 2.0 * (k2 * k2 + R2 * d.y * d.y)),
                       4.0 * (k2 * k1 + 2.0 * R2 * o.y * d.y), k1 * k1 + 4.0 * R2 * (o.y * o.y - r2)};
  double roots[poly::max_degree];
  const int n = poly::solve_polynomial(4, c, roots, p.b.x != 0.0, root_tolerance, tolerance::max_distance);
  for (int k = 0; k < n; ++k) {
    const double depth = (roots[k] + closer) / len;
    if (depth > torus_depth && depth < tolerance::max_distance) insert_sorted(out, depth);
  }
  return out;
}

Vec3 TorusShape::normal(const Primitive& p, Vec3 world_point) {
  const double major = p.a.x;
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const double from_axis = std::sqrt(q.x * q.x + q.z * q.z);
  Vec3 n = q;
  if (from_axis > tolerance::epsilon) n = q - Vec3{major * q.x / from_axis, 0.0, major * q.z / from_axis};
  if (p.transformed) n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

bool TorusShape::inside(const Primitive& p, Vec3 world_point) {
  const double major = p.a.x, minor = p.a.y;
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const double from_circle = std::sqrt(q.x * q.x + q.z * q.z) - major;
  const bool in = q.y * q.y + from_circle * from_circle <= minor * minor;
  return in != p.inverse;
}

Bounds TorusShape::object_bounds(const Primitive& p) {
  const double outer = p.a.x + p.a.y, r = p.a.y;
  return Bounds{Vec3{-outer, -r, -outer}, Vec3{outer, r, outer}};
}

// uv for uv_mapping as POV-Ray's Torus::CalcUV (torus.cpp): u = 1 − (atan2(z, x) + π)/2π around y,
// v = (atan2(y, r − R) + π)/2π around the tube.
std::array<double, 2> TorusShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  using uv_helpers::object_point;
  using uv_helpers::kTwoPi;
  const Primitive& p = *hit.leaf;
  const Vec3 q = object_point(p, world_point);
  const double u = 1.0 - (std::atan2(q.z, q.x) + M_PI) / kTwoPi;
  const double r = std::sqrt(q.x * q.x + q.z * q.z) - p.a.x;   // p.a.x: the major radius
  const double v = (std::atan2(q.y, r) + M_PI) / kTwoPi;
  return {u, v};
}

}  // namespace povtrace::render::shapes

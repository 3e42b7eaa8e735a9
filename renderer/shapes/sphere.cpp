// Sphere.
//
// SDL: `sphere { <Centre>, Radius  object_modifiers... }` (POV-Ray 3.7 reference "Sphere"; defaults centre <0,0,0>,
// radius 1). Surface |P - C| = r, solid interior.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/spheres.cpp, 3.7-stable):
// - Root finding is the half-chord form: with OC = C - O and tca = OC·D (D unit), the ray misses when the origin
//   is outside or on the sphere (|OC|² >= r²) and tca < EPSILON (1e-10), or when the squared half chord
//   r² - |OC|² + tca² is <= EPSILON (a grazing ray never hits).
// - A root is kept when DEPTH_TOLERANCE (1e-6) < depth < MAX_DISTANCE (1e7), both strict.
// - A transformed sphere ("ellipsoid" in POV-Ray) takes the world ray into object space, *normalises* the
//   object-space direction (length L), solves there, applies DEPTH_TOLERANCE and MAX_DISTANCE to the object-space
//   depth and reports depth / L as the world depth. So for a sphere scaled by 100 the near cut-off is 1e-4 in
//   world units: we do exactly the same, in the same space.
// - Inside: |P - C|² < r² strictly (object space for a transformed sphere); `inverse` turns it into |P - C|² > r²,
//   so a point exactly on the surface is outside either way.
// - Normal: untransformed (P - C) · (1/r) (not renormalised); transformed: object-space P - C carried to world by
//   the inverse transpose, then normalised by multiplying with the reciprocal length as POV-Ray's VNormalize does.
// - Bounds: the object-space cube C ± r (world_bounds carries its corners to world space).
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/sphere.hpp"
#include "renderer/shapes/uv_helpers.hpp"

namespace povtrace::render::shapes {

namespace {

// Half-chord intersection of a ray with unit direction. Returns false for a miss or a grazing ray.
bool solve_unit(Vec3 origin, Vec3 unit_direction, Vec3 centre, double radius_squared, double& t1, double& t2) {
  const Vec3 origin_to_centre = centre - origin;
  const double oc_squared = dot(origin_to_centre, origin_to_centre);
  const double closest_approach = dot(origin_to_centre, unit_direction);
  // Origin outside (or on) the sphere and the centre is not ahead: no root in front of the ray.
  if (oc_squared >= radius_squared && closest_approach < tolerance::epsilon) return false;
  const double half_chord_squared = radius_squared - oc_squared + closest_approach * closest_approach;
  if (!(half_chord_squared > tolerance::epsilon)) return false;
  const double half_chord = std::sqrt(half_chord_squared);
  t1 = closest_approach - half_chord;
  t2 = closest_approach + half_chord;
  return true;
}

bool depth_ok(double t) { return t > tolerance::sphere_depth && t < tolerance::max_distance; }

}  // namespace

Intersections SphereShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const double r2 = p.radius * p.radius;
  double t1 = 0, t2 = 0;
  if (!p.transformed) {
    if (solve_unit(ray.origin, ray.direction, p.a, r2, t1, t2)) {
      if (depth_ok(t1)) out.t[out.count++] = t1;
      if (depth_ok(t2)) out.t[out.count++] = t2;
    }
    return out;
  }
  const Vec3 origin = p.object_from_world.point(ray.origin);
  Vec3 direction = p.object_from_world.vector(ray.direction);
  const double len = std::sqrt(dot(direction, direction));
  direction *= 1.0 / len;  // POV-Ray scales by the reciprocal (VInverseScaleEq)
  if (solve_unit(origin, direction, p.a, r2, t1, t2)) {
    // Tolerances apply to the object-space depth; the reported depth is the world distance.
    if (depth_ok(t1)) out.t[out.count++] = t1 / len;
    if (depth_ok(t2)) out.t[out.count++] = t2 / len;
  }
  return out;
}

Vec3 SphereShape::normal(const Primitive& p, Vec3 world_point) {
  if (!p.transformed) return (world_point - p.a) * (1.0 / p.radius);
  const Vec3 local = p.object_from_world.point(world_point) - p.a;
  const Vec3 n = p.object_from_world.normal_from_inverse(local);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

bool SphereShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const Vec3 d = p.a - q;
  const double d2 = dot(d, d);
  const double r2 = p.radius * p.radius;
  return p.inverse ? d2 > r2 : d2 < r2;
}

Bounds SphereShape::object_bounds(const Primitive& p) {
  const double r = std::abs(p.radius);
  const Vec3 e{r, r, r};
  return Bounds{p.a - e, p.a + e};
}

Primitive SphereShape::build(const Sphere& s, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::sphere, world_from_object);
  p.a = s.centre;
  p.radius = s.radius;
  return p;
}

// uv for uv_mapping as POV-Ray's Sphere::UVCoord (spheres.cpp): in the sphere's own space (every transform
// undone), u the angle from +x towards +z over 2π, v the latitude 0.5 + asin(y)/π; at the poles (x² + z² ≤ 1e-10)
// u is 0.
std::array<double, 2> SphereShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  using uv_helpers::object_point;
  using uv_helpers::turn_around_y;
  const Primitive& p = *hit.leaf;
  Vec3 d = object_point(p, world_point) - p.a;
  const double len = length(d);
  if (len == 0.0) return {0.0, 0.0};
  d = d / len;
  const double v = 0.5 + std::asin(d.y) / M_PI;
  return {turn_around_y(d), v};
}

}  // namespace povtrace::render::shapes

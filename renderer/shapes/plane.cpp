// Plane.
//
// SDL: `plane { <Normal>, Distance  object_modifiers... }` (POV-Ray 3.7 reference "Plane"). The parser normalises
// the normal, so the surface is N·P = d with d measured along the unit normal. In a Primitive the plane is stored
// as a = N (unit), radius = d.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/planes.cpp, 3.7-stable):
// - A ray is parallel, and misses, when |N·D| < EPSILON (1e-10), D being the direction in the plane's space.
// - depth = (d - N·O) / (N·D); it is kept when DEPTH_TOLERANCE (1e-6) <= depth <= MAX_DISTANCE (1e7). POV-Ray's
//   comparisons here are inclusive (unlike the sphere's); we keep them inclusive.
// - A transformed plane takes origin and direction into object space *without* normalising the direction, so the
//   depth is already the world distance along the unit world ray and both tolerances apply to the world depth.
// - Inside: N·P - d < EPSILON (the side opposite to N, the surface and a 1e-10 skin included). POV-Ray implements
//   `inverse` by negating N and d, so the inverted test is -(N·P) + d < EPSILON (again surface included), which
//   is not the plain negation of the uninverted test; we reproduce the negated-plane form.
// - Normal: N, or for a transformed plane N carried to world space by the inverse transpose and normalised
//   (multiplication by the reciprocal length, as POV-Ray's VNormalize). `inverse` does not flip it here (the
//   shading side flips normals toward the viewer anyway).
// - Bounds: unbounded; the accelerator tests planes for every ray.
#include <cmath>
#include <limits>

#include "renderer/geometry.hpp"
#include "renderer/shapes/plane.hpp"

namespace povtrace::render::shapes {

Intersections PlaneShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const Vec3 origin = p.transformed ? p.object_from_world.point(ray.origin) : ray.origin;
  const Vec3 direction = p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction;
  const Vec3 n = p.a;
  const double normal_dot_direction = dot(n, direction);
  if (std::abs(normal_dot_direction) < tolerance::epsilon) return out;
  const double normal_dot_origin = dot(n, origin);
  const double t = -(normal_dot_origin - p.radius) / normal_dot_direction;
  if (t >= tolerance::plane_depth && t <= tolerance::max_distance) out.t[out.count++] = t;
  return out;
}

Vec3 PlaneShape::normal(const Primitive& p, Vec3 /*world_point*/) {
  if (!p.transformed) return p.a;
  const Vec3 n = p.object_from_world.normal_from_inverse(p.a);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

bool PlaneShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  const double s = dot(q, p.a);
  return p.inverse ? (-s + p.radius) < tolerance::epsilon : (s - p.radius) < tolerance::epsilon;
}

Bounds PlaneShape::world_bounds(const Primitive& /*p*/) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  return Bounds{{-inf, -inf, -inf}, {inf, inf, inf}};
}

Primitive PlaneShape::build(const Plane& plane, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::plane, world_from_object);
  p.a = plane.normal;
  p.radius = plane.distance;
  return p;
}

}  // namespace povtrace::render::shapes

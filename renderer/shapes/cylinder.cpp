// Cylinder.
//
// SDL: `cylinder { <P1>, <P2>, Radius [open]  object_modifiers... }` (POV-Ray 3.7 reference "Cylinder"). The
// primitive is POV-Ray's canonical cylinder x² + y² = 1, 0 <= z <= 1, placed by the canonical frame composed with
// the object's transforms (quadric_build.cpp; a cone with equal radii lands here too).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/cones.cpp, Cone::Intersect and friends
// with CYLINDER_FLAG, 3.7-stable):
// - The world ray is taken to canonical space and its direction normalised (length L); depths are canonical and
//   reported as depth / L.
// - Side: skipped when Dx² + Dy² <= EPSILON (ray along the axis); roots of the quadratic with discriminant >= 0
//   (a tangent ray hits) are kept when 1e-9 < depth < MAX_DISTANCE and 0 <= z <= 1 (ends included).
// - Caps (unless `open`), only when |Dz| > EPSILON: the planes z = 1 and z = 0, hit where x² + y² <= 1, with the
//   same depth window. A ray can so report a side root and a cap root at the same rim point.
// - Inside: x² + y² <= 1 + e and −e <= z <= 1 + e, with e = −EPSILON for a capped cylinder and +EPSILON for an
//   open one — `open` removes the caps from the surface, not from the solid. `inverse` negates the test.
// - Normal: POV-Ray knows the part hit; we take the part nearest to the canonical point (they agree except within
//   rounding of a rim): side (x, y, 0), top (0, 0, 1), bottom (0, 0, −1), carried to world by the inverse transpose
//   and normalised.
// - Bounds: the canonical box [−1, 1]² × [0, 1] carried to world.
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/insert_sorted.hpp"
#include "renderer/shapes/cylinder.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double cone_depth = 1e-9;   // cones.cpp Cone_Tolerance

bool depth_ok(double t) { return t > cone_depth && t < tolerance::max_distance; }
}  // namespace

Intersections CylinderShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const Vec3 o = p.object_from_world.point(ray.origin);
  Vec3 d = p.object_from_world.vector(ray.direction);
  const double len = std::sqrt(dot(d, d));
  d *= 1.0 / len;
  const double a = d.x * d.x + d.y * d.y;
  if (a > tolerance::epsilon) {
    const double b = o.x * d.x + o.y * d.y;
    const double c = o.x * o.x + o.y * o.y - 1.0;
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double root = std::sqrt(disc);
      for (const double t : {(-b + root) / a, (-b - root) / a}) {
        const double z = o.z + t * d.z;
        if (depth_ok(t) && z >= 0.0 && z <= 1.0) insert_sorted(out, t / len);
      }
    }
  }
  const bool capped = p.b.x != 0.0;
  if (capped && std::abs(d.z) > tolerance::epsilon) {
    for (const double plane : {1.0, 0.0}) {
      const double t = (plane - o.z) / d.z;
      const double x = o.x + t * d.x, y = o.y + t * d.y;
      if (x * x + y * y <= 1.0 && depth_ok(t)) insert_sorted(out, t / len);
    }
  }
  return out;
}

Vec3 CylinderShape::normal(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.object_from_world.point(world_point);
  Vec3 n{q.x, q.y, 0.0};
  if (p.b.x != 0.0) {
    const double to_side = std::abs(std::sqrt(q.x * q.x + q.y * q.y) - 1.0);
    const double to_top = std::abs(q.z - 1.0), to_bottom = std::abs(q.z);
    if (to_top < to_side && to_top <= to_bottom) n = Vec3{0, 0, 1};
    else if (to_bottom < to_side && to_bottom < to_top) n = Vec3{0, 0, -1};
  }
  n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

bool CylinderShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.object_from_world.point(world_point);
  const double e = p.b.x != 0.0 ? -tolerance::epsilon : tolerance::epsilon;
  const bool outside = q.x * q.x + q.y * q.y > 1.0 + e || q.z < -e || q.z > 1.0 + e;
  return outside == p.inverse;
}

Bounds CylinderShape::object_bounds(const Primitive&) { return Bounds{Vec3{-1, -1, 0}, Vec3{1, 1, 1}}; }

}  // namespace povtrace::render::shapes

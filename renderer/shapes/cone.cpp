// Cone.
//
// SDL: `cone { <P1>, R1, <P2>, R2 [open]  object_modifiers... }` (POV-Ray 3.7 reference "Cone"). The primitive is
// POV-Ray's canonical cone x² + y² = z² between z = dist (the small end, radius dist) and z = 1 (the big end,
// radius 1), placed by the canonical frame composed with the object's transforms (quadric_build.cpp, which also
// turns cones with equal radii into cylinders as POV-Ray does).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/cones.cpp, 3.7-stable):
// - The world ray goes to canonical space, direction normalised (length L); depths canonical, reported / L.
// - Side: a = Dx² + Dy² − Dz², b = Dx·Px + Dy·Py − Dz·Pz, c = Px² + Py² − Pz². With |a| < EPSILON the ray is
//   parallel to a generator: one root −c / (2b) when |b| > EPSILON. Otherwise the roots of the quadratic with
//   discriminant >= 0. A root is kept when 1e-9 < depth < MAX_DISTANCE and dist <= z <= 1 (this also rejects the
//   mirror nappe, z < 0, unless a negative radius made dist < 0: then POV-Ray draws the double cone, and so do we).
// - Caps (unless `open`), when |Dz| > EPSILON: z = 1 where x² + y² <= 1, z = dist where x² + y² <= dist².
// - Inside: x² + y² <= z² + e and dist − e <= z <= 1 + e, e = −EPSILON capped, +EPSILON open; `inverse` negates.
// - Normal: side (x, y, −z), big end (0, 0, 1), small end (0, 0, −1) — the part nearest to the canonical point,
//   POV-Ray remembers the part hit — carried to world by the inverse transpose and normalised.
// - Bounds: the canonical box [−1, 1]² × [dist, 1] carried to world.
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/insert_sorted.hpp"
#include "renderer/shapes/cone.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double cone_depth = 1e-9;   // cones.cpp Cone_Tolerance

bool depth_ok(double t) { return t > cone_depth && t < tolerance::max_distance; }
}  // namespace

Intersections ConeShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const double dist = p.radius;
  const Vec3 o = p.object_from_world.point(ray.origin);
  Vec3 d = p.object_from_world.vector(ray.direction);
  const double len = std::sqrt(dot(d, d));
  d *= 1.0 / len;
  const double a = d.x * d.x + d.y * d.y - d.z * d.z;
  const double b = d.x * o.x + d.y * o.y - d.z * o.z;
  const double c = o.x * o.x + o.y * o.y - o.z * o.z;
  auto side_root = [&](double t) {
    const double z = o.z + t * d.z;
    if (depth_ok(t) && z >= dist && z <= 1.0) insert_sorted(out, t / len);
  };
  if (std::abs(a) < tolerance::epsilon) {
    if (std::abs(b) > tolerance::epsilon) side_root(-0.5 * c / b);
  } else {
    const double disc = b * b - a * c;
    if (disc >= 0.0) {
      const double root = std::sqrt(disc);
      side_root((-b - root) / a);
      side_root((-b + root) / a);
    }
  }
  const bool capped = p.b.x != 0.0;
  if (capped && std::abs(d.z) > tolerance::epsilon) {
    const double planes[2] = {1.0, dist};
    const double radius_squared[2] = {1.0, dist * dist};
    for (int k = 0; k < 2; ++k) {
      const double t = (planes[k] - o.z) / d.z;
      const double x = o.x + t * d.x, y = o.y + t * d.y;
      if (x * x + y * y <= radius_squared[k] && depth_ok(t)) insert_sorted(out, t / len);
    }
  }
  return out;
}

Vec3 ConeShape::normal(const Primitive& p, Vec3 world_point) {
  const double dist = p.radius;
  const Vec3 q = p.object_from_world.point(world_point);
  Vec3 n{q.x, q.y, -q.z};
  if (p.b.x != 0.0) {
    // Distance to the side x² + y² = z² measured across it (the generators are at 45° in canonical space).
    const double to_side = std::abs(std::sqrt(q.x * q.x + q.y * q.y) - std::abs(q.z)) * M_SQRT1_2;
    const double to_top = std::abs(q.z - 1.0), to_bottom = std::abs(q.z - dist);
    if (to_top < to_side && to_top <= to_bottom) n = Vec3{0, 0, 1};
    else if (to_bottom < to_side && to_bottom < to_top) n = Vec3{0, 0, -1};
  }
  n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

bool ConeShape::inside(const Primitive& p, Vec3 world_point) {
  const double dist = p.radius;
  const Vec3 q = p.object_from_world.point(world_point);
  const double e = p.b.x != 0.0 ? -tolerance::epsilon : tolerance::epsilon;
  const bool outside = q.x * q.x + q.y * q.y > q.z * q.z + e || q.z < dist - e || q.z > 1.0 + e;
  return outside == p.inverse;
}

Bounds ConeShape::object_bounds(const Primitive& p) { return Bounds{Vec3{-1, -1, p.radius}, Vec3{1, 1, 1}}; }

}  // namespace povtrace::render::shapes

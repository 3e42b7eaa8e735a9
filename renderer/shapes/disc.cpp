// Disc.
//
// SDL: `disc { <Centre>, <Normal>, Radius [, Hole_Radius]  object_modifiers... }` (POV-Ray 3.7 reference "Disc").
// The primitive is the canonical plane z = 0 (an annulus hole² <= x² + y² <= radius²) placed by the frame
// (centre, normal) composed with the object's transforms (quadric_build.cpp).
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/discs.cpp, 3.7-stable):
// - The world ray goes to canonical space, direction normalised (length L). Rays with |Dz| <= EPSILON (parallel
//   to the disc) miss. The plane depth t must be >= 0; the hit counts when hole² <= x² + y² <= radius² (both
//   edges included), and the *world* depth t / L must lie in (1e-6, MAX_DISTANCE).
// - Inside: the half-space behind the normal, canonical z < 0 (the disc's plane itself is outside); `inverse`
//   negates the test.
// - Normal: the written normal carried by the object's transforms and normalised, the same at every point.
// - Bounds: the canonical box [−r, r]² × [−SMALL_TOLERANCE, SMALL_TOLERANCE] (1e-3) carried to world.
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/disc.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double disc_depth = 1e-6;        // discs.cpp DEPTH_TOLERANCE
constexpr double small_tolerance = 1e-3;   // SMALL_TOLERANCE, the disc's bounding box thickness
}  // namespace

Intersections DiscShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const Vec3 o = p.object_from_world.point(ray.origin);
  Vec3 d = p.object_from_world.vector(ray.direction);
  const double len = std::sqrt(dot(d, d));
  d *= 1.0 / len;
  if (!(std::abs(d.z) > tolerance::epsilon)) return out;
  const double t = -o.z / d.z;
  if (!(t >= 0.0)) return out;
  const double x = o.x + t * d.x, y = o.y + t * d.y;
  const double r2 = x * x + y * y;
  if (!(r2 >= p.a.x && r2 <= p.a.y)) return out;
  const double depth = t / len;
  if (depth > disc_depth && depth < tolerance::max_distance) out.t[out.count++] = depth;
  return out;
}

Vec3 DiscShape::normal(const Primitive& p, Vec3) { return p.b; }

bool DiscShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.object_from_world.point(world_point);
  return (q.z >= 0.0) == p.inverse;
}

Bounds DiscShape::object_bounds(const Primitive& p) {
  const double r = std::sqrt(p.a.y);
  return Bounds{Vec3{-r, -r, -small_tolerance}, Vec3{r, r, small_tolerance}};
}

}  // namespace povtrace::render::shapes

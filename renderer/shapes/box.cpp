// Box.
//
// SDL: `box { <Corner1>, <Corner2>  object_modifiers... }` (POV-Ray 3.7 reference "Box"). The parser sorts the
// corners per axis; a Primitive stores them as a = lo, b = hi. The solid is the closed axis-aligned box in object
// space.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/boxes.cpp, 3.7-stable):
// - Slab test in object space with the *unnormalised* object-space direction, so every depth is directly the world
//   distance along the unit world ray and the tolerances below apply to world depths.
// - The entry/exit interval starts as [0, BOUND_HUGE]; there is no MAX_DISTANCE for boxes. An axis whose direction
//   component is within ±EPSILON (1e-10) is treated as parallel: the ray misses unless the origin lies within that
//   slab (boundary included).
// - Slabs are processed x, y, z. For y and z a new exit (entry) only replaces the current one when it is smaller
//   (larger) by more than CLOSE_TOLERANCE (1e-6); near-ties keep the earlier value. This tie rule can move the
//   reported depth by up to 1e-6 near edges, so we keep it.
// - The ray misses if the exit depth is < DEPTH_TOLERANCE (1e-6). The entry depth is reported only when it is
//   > DEPTH_TOLERANCE; the exit depth is always reported.
// - Inside: the closed box (boundary inside); `inverse` negates the test exactly (boundary outside).
// - Normal: the face each root came from, as POV-Ray records it (Side1/Side2, kept in SurfaceHit::element). On a
//   near-tie of two slabs (within CLOSE_TOLERANCE) the depth is the earlier slab's and the face is the one the
//   ray runs more steeply into. Those ties lie within 1e-6 of an edge in depth, a sliver at ordinary scales but
//   a whole pixel once the box is 1e-4 across. Transformed boxes carry the axis normal to world space by the
//   inverse transpose and normalise it. BoxShape::normal, for callers that have only a point, picks the face whose
//   plane is nearest to it.
#include <cmath>

#include "renderer/geometry.hpp"
#include "renderer/shapes/box.hpp"
#include "renderer/shapes/uv_helpers.hpp"

namespace povtrace::render::shapes {

namespace {
constexpr double close_tolerance = 1e-6;  // boxes.cpp CLOSE_TOLERANCE: slab depths this close count as a tie
}

Intersections BoxShape::intersect(const Primitive& p, const Ray& ray) {
  Intersections out;
  const Vec3 origin = p.transformed ? p.object_from_world.point(ray.origin) : ray.origin;
  const Vec3 direction = p.transformed ? p.object_from_world.vector(ray.direction) : ray.direction;
  double t_enter = 0.0;
  double t_exit = tolerance::bound_huge;
  std::uint32_t side_enter = 0, side_exit = 0;   // POV-Ray's smin, smax: 2·axis + 1 for the high face
  for (int axis = 0; axis < 3; ++axis) {
    const double d = direction[axis];
    const double o = origin[axis];
    const double lo = p.a[axis];
    const double hi = p.b[axis];
    if (d < -tolerance::epsilon || d > tolerance::epsilon) {
      // The x slab takes any strictly better depth; y and z need to beat the current one by the tie tolerance.
      // On a near-tie the depth stays and the face becomes this axis' when the ray runs more along this axis
      // than along the current face's (POV-Ray's "which side is most probably hit").
      const double tie = axis == 0 ? 0.0 : close_tolerance;
      const auto steeper = [&](std::uint32_t side) { return std::fabs(d) > std::fabs(direction[side / 2]); };
      const auto exit_side = static_cast<std::uint32_t>(2 * axis + (d < 0 ? 0 : 1));
      const auto enter_side = static_cast<std::uint32_t>(2 * axis + (d < 0 ? 1 : 0));
      const double exit_plane = d < 0 ? lo : hi;
      const double enter_plane = d < 0 ? hi : lo;
      const double t_far = (exit_plane - o) / d;
      if (t_far < t_enter) return out;
      if (t_far <= t_exit - tie) {
        t_exit = t_far;
        side_exit = exit_side;
      } else if (t_far <= t_exit + tie && steeper(side_exit)) {
        side_exit = exit_side;
      }
      const double t_near = (enter_plane - o) / d;
      if (t_near >= t_enter + tie) {
        if (t_near > t_exit) return out;
        t_enter = t_near;
        side_enter = enter_side;
      } else if (t_near >= t_enter - tie && axis > 0 && steeper(side_enter)) {
        side_enter = enter_side;
      }
    } else if (o < lo || o > hi) {
      return out;  // parallel to this slab and outside it
    }
  }
  if (t_exit < tolerance::box_depth) return out;
  if (t_enter > tolerance::box_depth) {
    out.element[out.count] = side_enter;
    out.t[out.count++] = t_enter;
  }
  out.element[out.count] = side_exit;
  out.t[out.count++] = t_exit;
  return out;
}

// POV-Ray's Box::Normal: the axis normal of the face recorded with the root, carried to world space.
Vec3 BoxShape::face_normal(const Primitive& p, std::uint32_t side) {
  Vec3 n{};
  n[static_cast<int>(side / 2)] = side % 2 == 1 ? 1.0 : -1.0;
  if (!p.transformed) return n;
  n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

Vec3 BoxShape::normal(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  int best_axis = 0;
  double best_sign = -1.0;
  double best_distance = std::abs(q.x - p.a.x);
  for (int axis = 0; axis < 3; ++axis) {
    const double to_lo = std::abs(q[axis] - p.a[axis]);
    const double to_hi = std::abs(q[axis] - p.b[axis]);
    if (to_lo < best_distance) {
      best_distance = to_lo;
      best_axis = axis;
      best_sign = -1.0;
    }
    if (to_hi < best_distance) {
      best_distance = to_hi;
      best_axis = axis;
      best_sign = 1.0;
    }
  }
  Vec3 n{};
  n[best_axis] = best_sign;
  if (!p.transformed) return n;
  n = p.object_from_world.normal_from_inverse(n);
  return n * (1.0 / std::sqrt(dot(n, n)));
}

bool BoxShape::inside(const Primitive& p, Vec3 world_point) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world_point) : world_point;
  for (int axis = 0; axis < 3; ++axis)
    if (q[axis] < p.a[axis] || q[axis] > p.b[axis]) return p.inverse;
  return !p.inverse;
}

Bounds BoxShape::object_bounds(const Primitive& p) { return Bounds{p.a, p.b}; }

Primitive BoxShape::build(const Box& box, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::box, world_from_object);
  p.a = box.corner1;
  p.b = box.corner2;
  return p;
}

// uv for uv_mapping as POV-Ray's Box::UVCoord (boxes.cpp): the point normalised to the box ([0, 1] per axis); each
// face gets its own region of a 4 × 3 cube layout (−x: u = z/4, v = 1/3 + y/3; +x: u = 3/4 − z/4; −y: u = 1/4 + x/4,
// v = z/3; +y: v = 1 − z/3; −z: u = 1 − x/4; +z: u = 1/4 + x/4; the four side faces v = 1/3 + y/3).
// The face the point lies on, as box_normal picks it: the nearest of the six planes (axis, and the high side).
std::array<double, 2> BoxShape::uv(const SurfaceHit& hit, Vec3 world_point) {
  using uv_helpers::object_point;
  const Primitive& p = *hit.leaf;
  const Vec3 q = object_point(p, world_point);
  int axis = 0;
  bool high = false;
  double best = std::abs(q.x - p.a.x);
  for (int k = 0; k < 3; ++k) {
    if (const double d = std::abs(q[k] - p.a[k]); d < best) { best = d; axis = k; high = false; }
    if (const double d = std::abs(q[k] - p.b[k]); d < best) { best = d; axis = k; high = true; }
  }
  const Vec3 diff = p.b - p.a;
  const Vec3 n{(q.x - p.a.x) / diff.x, (q.y - p.a.y) / diff.y, (q.z - p.a.z) / diff.z};
  const double side_v = 1.0 / 3.0 + n.y / 3.0;
  switch (axis * 2 + (high ? 1 : 0)) {
    case 0: return {n.z / 4.0, side_v};
    case 1: return {3.0 / 4.0 - n.z / 4.0, side_v};
    case 2: return {1.0 / 4.0 + n.x / 4.0, n.z / 3.0};
    case 3: return {1.0 / 4.0 + n.x / 4.0, 3.0 / 3.0 - n.z / 3.0};
    case 4: return {1.0 - n.x / 4.0, side_v};
    default: return {1.0 / 4.0 + n.x / 4.0, side_v};
  }
}

}  // namespace povtrace::render::shapes

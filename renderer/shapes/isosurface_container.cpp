// The ray's span through an isosurface's container, as POV-Ray 3.7 computes it (source/backend/shape/boxes.cpp
// Box::Intersect, spheres.cpp Sphere::Intersect, 3.7-stable; read for the behaviour only):
// - box: slabs x, y, z from [0, BOUND_HUGE] with the unnormalised direction (depths are world depths); an axis
//   whose direction is within 1e-10 of 0 needs the origin inside its slab. For y and z a new exit (entry) replaces
//   the current one only when nearer (farther) by more than 1e-6; within 1e-6 the face changes to the new axis
//   when the ray runs more along it (y against x; z against the axis of the face kept). No span when the exit is
//   below 1e-6.
// - sphere: with a unit direction, none when the origin is outside (or on) the sphere and the closest approach is
//   not ahead by 1e-10, or when the squared half chord is at most 1e-10.
#include <cmath>

#include "renderer/shapes/isosurface.hpp"

namespace povtrace::render {

namespace {
constexpr double close_tolerance = 1e-6;   // boxes.cpp CLOSE_TOLERANCE
constexpr double box_depth = 1e-6;         // boxes.cpp DEPTH_TOLERANCE

int side_of(int axis, bool upper) { return 1 + 2 * axis + (upper ? 1 : 0); }
int axis_of(int side) { return (side - 1) / 2; }

// Within the tie tolerance, whether the face of `axis` should replace face `current`.
bool tie_prefers(Vec3 d, int axis, int current) {
  if (axis == 1) return std::fabs(d.y) > std::fabs(d.x);
  if (current == 0 || axis_of(current) == 2) return false;
  return std::fabs(d.z) > std::fabs(d[axis_of(current)]);
}
}  // namespace

std::optional<ContainerSpan> box_container_span(Vec3 p, Vec3 d, Vec3 corner1, Vec3 corner2) {
  ContainerSpan s{0.0, tolerance::bound_huge, 0, 0};
  for (int axis = 0; axis < 3; ++axis) {
    const double v = d[axis];
    if (!(v < -tolerance::epsilon || v > tolerance::epsilon)) {
      if (p[axis] < corner1[axis] || p[axis] > corner2[axis]) return std::nullopt;
      continue;
    }
    const bool ahead = v > 0.0;
    const double tie = axis == 0 ? 0.0 : close_tolerance;
    double t = ((ahead ? corner2 : corner1)[axis] - p[axis]) / v;
    if (t < s.t1) return std::nullopt;
    if (t <= s.t2 - tie) {
      s.side2 = side_of(axis, ahead), s.t2 = t;
    } else if (axis > 0 && t <= s.t2 + tie && tie_prefers(d, axis, s.side2)) {
      s.side2 = side_of(axis, ahead);
    }
    t = ((ahead ? corner1 : corner2)[axis] - p[axis]) / v;
    if (t >= s.t1 + tie) {
      if (t > s.t2) return std::nullopt;
      s.side1 = side_of(axis, !ahead), s.t1 = t;
    } else if (axis > 0 && t >= s.t1 - tie && tie_prefers(d, axis, s.side1)) {
      s.side1 = side_of(axis, !ahead);
    }
  }
  if (!(s.t2 >= box_depth)) return std::nullopt;
  return s;
}

std::optional<ContainerSpan> sphere_container_span(Vec3 p, Vec3 d, Vec3 centre, double radius) {
  const Vec3 to_centre = centre - p;
  const double oc2 = dot(to_centre, to_centre), r2 = radius * radius;
  const double closest = dot(to_centre, d);
  if (oc2 >= r2 && closest < tolerance::epsilon) return std::nullopt;
  const double half2 = r2 - oc2 + closest * closest;
  if (!(half2 > tolerance::epsilon)) return std::nullopt;
  const double half = std::sqrt(half2);
  return ContainerSpan{closest - half, closest + half, 0, 0};
}

}  // namespace povtrace::render

// What the uv functions of the sphere, lathe, sor, box and torus (each in its shape's file) share: the hit point in
// the shape's own space, and POV-Ray's angle around y.
#pragma once

#include <cmath>

#include "renderer/geometry.hpp"

namespace povtrace::render::shapes::uv_helpers {

inline constexpr double kTwoPi = 2.0 * M_PI;

// The world point in the shape's own space (uv is computed there, every transform undone).
inline Vec3 object_point(const Primitive& p, Vec3 world_point) {
  return p.transformed ? p.object_from_world.point(world_point) : world_point;
}

// The angle around y from +x toward +z as a fraction of a turn, 0 near the axis (x² + z² ≤ 1e-10): POV-Ray's
// Sphere, Lathe and Sor UVCoord share this.
inline double turn_around_y(Vec3 d) {
  const double flat2 = d.x * d.x + d.z * d.z;
  if (!(flat2 > tolerance::epsilon)) return 0.0;
  const double flat = std::sqrt(flat2);
  double theta = 0.0;
  if (d.z == 0.0) theta = d.x > 0 ? 0.0 : M_PI;
  else {
    theta = std::acos(d.x / flat);
    if (d.z < 0.0) theta = kTwoPi - theta;
  }
  return theta / kTwoPi;
}

}  // namespace povtrace::render::shapes::uv_helpers

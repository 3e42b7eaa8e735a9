// The mapping warps and the black hole, as POV-Ray 3.7's Warp_EPoint applies them (facts from
// source/backend/pattern/warps.cpp warp_planar, warp_cylindrical, warp_spherical, warp_toroidal, warp_cubic and
// the BLACK_HOLE_WARP case, 3.7-stable; docs/issue21-warps.md):
// - planar keeps x and y and puts the written distance in z; cylindrical gives (angle / 2π, y, distance from y);
//   spherical (angle / 2π, 0.5 + asin(y / r) / π, r); toroidal (angle / 2π, the angle around the tube / 2π, the
//   distance from the major circle); dist_exp scales the angles by the distance to that power. Points on the axis
//   (the origin for spherical) are left as they are.
// - The orientation is no rotation: unless it is exactly +z, the result is the blend ox·(w, v, −u) + oy·(u, −w, v) +
//   oz·(u, v, w) of the mapped (u, v, w).
// - cubic unfolds the cube around the origin onto a cross in [0, 1]², z the largest coordinate's size.
// - A black hole pushes points within its radius away from its centre (towards it when inverse) by
//   min(1, ((radius − d) / radius)^falloff · strength) of their offset; with repeat its centre repeats per cell,
//   jittered by `turbulence` times POV-Ray's random table at the cell's hash.
#include <cmath>

#include "renderer/pattern/pattern_functions.hpp"
#include "runtime/noise.hpp"

namespace povtrace::render::patterns {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON
constexpr double kTwoPi = 2.0 * M_PI;

Vec3 oriented(double u, double v, double w, Vec3 o) {
  if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return {u, v, w};
  return {(o.x * w + o.y * u) + o.z * u, (o.x * v + o.y * (-w)) + o.z * v, (o.x * (-u) + o.y * v) + o.z * w};
}

// dist_exp: the angles scaled by the distance to that power (1 multiplies by the distance itself).
double distance_scale(double distance, double dist_exp) {
  return dist_exp == 1.0 ? distance : std::pow(distance, dist_exp);
}

Vec3 cylindrical(Vec3 p, const MappingWarp& w) {
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  if (rho == 0.0) return p;
  double theta = angle_around_y(p.x, p.z, rho) / kTwoPi;
  if (w.dist_exp != 0.0) theta = theta * distance_scale(rho, w.dist_exp);
  return oriented(theta, p.y, rho, w.orientation);
}

Vec3 spherical(Vec3 p, const MappingWarp& w) {
  const double r = std::sqrt((p.x * p.x + p.y * p.y) + p.z * p.z);
  if (r == 0.0) return p;
  const double nx = p.x / r, ny = p.y / r, nz = p.z / r;
  double phi = 0.5 + std::asin(ny) / M_PI;
  const double rho = std::sqrt(nx * nx + nz * nz);
  double theta = rho == 0.0 ? 0.0 : angle_around_y(nx, nz, rho) / kTwoPi;
  if (w.dist_exp != 0.0) {
    const double k = distance_scale(r, w.dist_exp);
    theta = theta * k;
    phi = phi * k;
  }
  return oriented(theta, phi, r, w.orientation);
}

Vec3 toroidal(Vec3 p, const MappingWarp& w) {
  const double rho = std::sqrt(p.x * p.x + p.z * p.z);
  if (rho == 0.0) return p;
  double theta = 0.0 - angle_around_y(p.x, p.z, rho);
  const double dx = rho - w.major_radius;
  const double d = std::sqrt(dx * dx + p.y * p.y);
  double phi = std::acos((-dx) / d);
  if (p.y > 0.0) phi = kTwoPi - phi;
  theta = theta / (-kTwoPi);
  phi = phi / kTwoPi;
  if (w.dist_exp != 0.0) {
    const double k = distance_scale(d, w.dist_exp);
    theta = theta * k;
    phi = phi * k;
  }
  return oriented(theta, phi, d, w.orientation);
}

// One face of the unfolded cube: (a / along + 1) scaled into the face's quarter or third.
double face(double base, double scale, double a, double along, bool minus) {
  const double t = (scale * (a / along + 1.0)) / 2.0;
  return minus ? base - t : base + t;
}

Vec3 cubic(Vec3 p) {
  const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
  constexpr double third = 1.0 / 3.0;
  if (p.x >= 0 && p.x >= ay && p.x >= az)
    return {face(0.75, 0.25, p.z, p.x, true), face(third, third, p.y, p.x, false), p.x};
  if (p.y >= 0 && p.y >= ax && p.y >= az)
    return {face(0.25, 0.25, p.x, p.y, false), face(1.0, third, p.z, p.y, true), p.y};
  if (p.z >= 0 && p.z >= ax && p.z >= ay)
    return {face(0.25, 0.25, p.x, p.z, false), face(third, third, p.y, p.z, false), p.z};
  if (p.x < 0 && p.x <= -ay && p.x <= -az) {
    const double x = -p.x;
    return {(0.25 * (p.z / x + 1.0)) / 2.0, face(third, third, p.y, x, false), x};
  }
  if (p.y < 0 && p.y <= -ax && p.y <= -az) {
    const double y = -p.y;
    return {face(0.25, 0.25, p.x, y, false), (third * (p.z / y + 1.0)) / 2.0, y};
  }
  const double z = -p.z;
  return {face(1.0, 0.25, p.x, z, true), face(third, third, p.y, z, false), z};
}

int cell_of(double v, double width) { return static_cast<int>(std::floor(v / width)); }
}  // namespace

Vec3 mapping_warp(Vec3 p, const MappingWarp& w) {
  switch (w.kind) {
    case MappingWarpKind::planar: return oriented(p.x, p.y, w.offset, w.orientation);
    case MappingWarpKind::cylindrical: return cylindrical(p, w);
    case MappingWarpKind::spherical: return spherical(p, w);
    case MappingWarpKind::toroidal: return toroidal(p, w);
    case MappingWarpKind::cubic: return cubic(p);
  }
  return p;
}

Vec3 black_hole_warp(Vec3 p, const BlackHoleWarp& w, int cell[3]) {
  Vec3 c = w.centre;
  if (w.repeat) {
    const Vec3& r = w.repeat_vector;
    if (r.x >= kEpsilon) cell[0] = cell_of(p.x, r.x);
    if (r.y >= kEpsilon) cell[1] = cell_of(p.y, r.y);
    if (r.z >= kEpsilon) cell[2] = cell_of(p.z, r.z);
    if (w.uncertain) {
      const std::size_t s = lattice_hash3(cell[0], cell[1], cell[2]);
      c.x = c.x + pattern_random(s) * w.uncertainty.x;
      c.y = c.y + pattern_random(s + 1) * w.uncertainty.y;
      c.z = c.z + pattern_random(s + 2) * w.uncertainty.z;
    }
    c.x = c.x + r.x * static_cast<double>(cell[0]);
    c.y = c.y + r.y * static_cast<double>(cell[1]);
    c.z = c.z + r.z * static_cast<double>(cell[2]);
  }
  const Vec3 d = p - c;
  const double length = std::sqrt((d.x * d.x + d.y * d.y) + d.z * d.z);
  if (length >= w.radius || w.type != 0) return p;
  double strength = std::pow((w.radius - length) / w.radius, w.falloff) * w.strength;
  if (strength > 1.0) strength = 1.0;
  const double k = w.inverse ? -strength : strength;
  return {p.x + d.x * k, p.y + d.y * k, p.z + d.z * k};
}

}  // namespace povtrace::render::patterns

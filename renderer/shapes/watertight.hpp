// Watertight ray/triangle intersection (Woop, Benthin, Wald, "Watertight Ray/Triangle Intersection", JCGT 2013).
//
// The ray is sheared once so that it runs along +z through the origin; every vertex is then carried into that
// frame by a computation that depends only on the vertex and the ray, never on the triangle. The three 2-D edge
// functions of a triangle are computed from those transformed vertices, so two triangles sharing an edge compute
// the same edge function with opposite signs, bit for bit (a·b − c·d against c·d − a·b): a ray can never pass
// between them. A point exactly on an edge (an edge function of exactly 0) counts as inside both, and an edge
// function that rounds to 0 is recomputed in extended precision, as the paper recommends, so the zero test itself
// is exact where it matters.
#pragma once

#include <cmath>

#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

// A ray prepared for the watertight test: the axis the direction is largest along becomes z (x and y swapped when
// that direction is negative, to keep the winding), and the shear that maps the direction onto z.
struct ShearedRay {
  Vec3 origin;
  int kx = 0, ky = 1, kz = 2;
  double sx = 0, sy = 0, sz = 1;

  explicit ShearedRay(const Ray& ray) : origin(ray.origin) {
    const Vec3 d = ray.direction;
    kz = std::fabs(d.x) > std::fabs(d.y) ? (std::fabs(d.x) > std::fabs(d.z) ? 0 : 2)
                                         : (std::fabs(d.y) > std::fabs(d.z) ? 1 : 2);
    kx = (kz + 1) % 3;
    ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);
    sx = d[kx] / d[kz];
    sy = d[ky] / d[kz];
    sz = 1.0 / d[kz];
  }
};

// A hit of the watertight test: depth along the ray (in the ray's own length units) and the barycentric weights
// of the second and third vertex (the first has 1 − u − v).
struct TriangleHit {
  double t = 0, u = 0, v = 0;
};

namespace detail {
// The edge function of two sheared vertices; recomputed in extended precision when it rounds to zero.
inline double edge(double ax, double ay, double bx, double by) {
  const double e = ax * by - ay * bx;
  if (e != 0.0) return e;
  return static_cast<double>(static_cast<long double>(ax) * by - static_cast<long double>(ay) * bx);
}
}  // namespace detail

// Intersects the ray with triangle (a, b, c), either side facing. False for a miss, a ray in the triangle's plane
// or a degenerate triangle; no depth limits are applied here (callers apply their shape's tolerances).
inline bool intersect_watertight(const ShearedRay& r, Vec3 a, Vec3 b, Vec3 c, TriangleHit& hit) {
  const Vec3 A = a - r.origin, B = b - r.origin, C = c - r.origin;
  const double ax = A[r.kx] - r.sx * A[r.kz], ay = A[r.ky] - r.sy * A[r.kz];
  const double bx = B[r.kx] - r.sx * B[r.kz], by = B[r.ky] - r.sy * B[r.kz];
  const double cx = C[r.kx] - r.sx * C[r.kz], cy = C[r.ky] - r.sy * C[r.kz];
  const double U = detail::edge(cx, cy, bx, by);
  const double V = detail::edge(ax, ay, cx, cy);
  const double W = detail::edge(bx, by, ax, ay);
  if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return false;
  const double det = U + V + W;
  if (det == 0.0) return false;
  const double az = r.sz * A[r.kz], bz = r.sz * B[r.kz], cz = r.sz * C[r.kz];
  const double t_scaled = U * az + V * bz + W * cz;
  hit.t = t_scaled / det;
  hit.u = V / det;
  hit.v = W / det;
  return true;
}

}  // namespace povtrace::render::shapes

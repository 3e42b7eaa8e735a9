// Helpers shared by the cylinder, cone, disc and torus tests: primitives built from scene descriptions exactly as
// render_scene.cpp builds them, and an independent reference for where a ray crosses a solid's boundary (marching
// on a membership test in the object's own written terms, then bisection).
#pragma once

#include <functional>
#include <vector>

#include "geometry_kit.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/quadric_shapes.hpp"

namespace povtrace::test {


// Where along the ray (in (t_begin, t_end)) the membership function changes value, by marching `steps` equal
// steps and bisecting each change to rounding. The ray's direction is unit length.
inline std::vector<double> crossings(const std::function<bool(Vec3)>& member, const render::Ray& r, double t_begin,
                                     double t_end, int steps) {
  std::vector<double> out;
  auto at = [&](double t) { return member(r.origin + r.direction * t); };
  double t0 = t_begin;
  bool m0 = at(t0);
  for (int k = 1; k <= steps; ++k) {
    const double t1 = t_begin + (t_end - t_begin) * k / steps;
    const bool m1 = at(t1);
    if (m1 != m0) {
      double lo = t0, hi = t1;
      for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        if (mid <= lo || mid >= hi) break;
        if (at(mid) == m0) lo = mid; else hi = mid;
      }
      out.push_back(0.5 * (lo + hi));
    }
    t0 = t1;
    m0 = m1;
  }
  return out;
}

// The world normal of an object-space normal under world_from_object (inverse transpose), normalised.
inline Vec3 world_normal(const Matrix& world_from_object, Vec3 object_normal) {
  const Vec3 n = world_from_object.inverse().normal_from_inverse(object_normal);
  return n / length(n);
}

}  // namespace povtrace::test

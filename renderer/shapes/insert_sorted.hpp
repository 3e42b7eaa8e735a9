// Adds a depth to a shape's Intersections keeping them ascending (the shapes with several surfaces — cylinder and
// cone side plus caps, the torus's quartic — find their roots out of order). At most capacity roots are added.
#pragma once

#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

inline void insert_sorted(Intersections& out, double t) {
  if (out.count >= Intersections::capacity) return;
  int k = out.count++;
  while (k > 0 && out.t[k - 1] > t) {
    out.t[k] = out.t[k - 1];
    --k;
  }
  out.t[k] = t;
}

}  // namespace povtrace::render::shapes

#include "scene/extent_box.hpp"

namespace povtrace {

ExtentBox ExtentBox::make(Vec3 lower, Vec3 lengths) {
  ExtentBox b;
  for (int i = 0; i < 3; ++i) {
    b.lower[i] = static_cast<float>(lower[i]);
    b.lengths[i] = static_cast<float>(lengths[i]);
  }
  return b;
}

ExtentBox ExtentBox::from_min_max(Vec3 lo, Vec3 hi) { return make(lo, hi - lo); }

ExtentBox ExtentBox::huge() {
  return make({-kBoundHuge / 2, -kBoundHuge / 2, -kBoundHuge / 2}, {kBoundHuge, kBoundHuge, kBoundHuge});
}

// In POV-Ray's order (corners 1 to 8, the lower corner last) keeping the first of equal values, so that a -0 and a
// +0 end as in POV-Ray.
ExtentBox ExtentBox::transformed(const Matrix& m) const {
  double lo_w[3] = {kBoundHuge, kBoundHuge, kBoundHuge}, hi_w[3] = {-kBoundHuge, -kBoundHuge, -kBoundHuge};
  for (int i = 1; i <= 8; ++i) {
    const Vec3 corner{double(lower[0]) + ((i & 1) ? double(lengths[0]) : 0.0),
                      double(lower[1]) + ((i & 2) ? double(lengths[1]) : 0.0),
                      double(lower[2]) + ((i & 4) ? double(lengths[2]) : 0.0)};
    const Vec3 p = m.point(corner);
    const double c[3] = {p.x, p.y, p.z};
    for (int k = 0; k < 3; ++k) {
      if (c[k] < lo_w[k]) lo_w[k] = c[k];
      if (c[k] > hi_w[k]) hi_w[k] = c[k];
    }
  }
  const Vec3 lo_v{lo_w[0], lo_w[1], lo_w[2]}, hi_v{hi_w[0], hi_w[1], hi_w[2]};
  const Vec3 limit{kBoundHuge / 2, kBoundHuge / 2, kBoundHuge / 2};
  return from_min_max(max(lo_v, -1.0 * limit), min(hi_v, limit));
}

}  // namespace povtrace

// nearest_spot (sweep.hpp): a point on a lathe, prism or sor surface shares its u or its v with the profile point
// it lies on, so the candidates are the parameters where x(w) = ±u or y(w) = v.
#include <cmath>

#include "runtime/polynomial_roots.hpp"
#include "renderer/shapes/sweep.hpp"

namespace povtrace::render {

namespace {
// Roots in [0, 1] of c(w) = value.
int level_roots(const Cubic& c, double value, double* w) {
  const double k[4] = {c[0], c[1], c[2], c[3] - value};
  double roots[3];
  const int n = poly::solve_polynomial(3, k, roots, false, 0.0, tolerance::max_distance);
  int m = 0;
  for (int j = 0; j < n; ++j)
    if (roots[j] >= 0.0 && roots[j] <= 1.0) w[m++] = roots[j];
  return m;
}
}  // namespace

ProfileSpot nearest_spot(const ProfileSegment& s, double u, double v, bool radial) {
  ProfileSpot best;
  double w[9];
  int n = level_roots(s.y, v, w);
  n += level_roots(s.x, u, w + n);
  if (radial) n += level_roots(s.x, -u, w + n);
  for (int j = 0; j < n; ++j) {
    const double x = evaluate(s.x, w[j]);
    const double du = (radial ? std::fabs(x) : x) - u, dv = evaluate(s.y, w[j]) - v;
    const double dist = std::sqrt(du * du + dv * dv);
    if (dist < best.distance) best = ProfileSpot{w[j], dist};
  }
  return best;
}

}  // namespace povtrace::render

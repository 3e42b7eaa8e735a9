// The real roots of a quadratic, as povtrace has always solved them (the closed form POV-Ray's Solve_Polynomial
// uses for degree 2, written without its cancellation). One definition for both sides: the parser finds the turning
// points of lathe, prism and sor profiles with it (runtime/sweep_extents.cpp, for their bounding boxes), and the
// polynomial solver the renderer's shapes call (runtime/polynomial_roots.hpp) uses it for its quadratics, so that the
// bounding boxes the SDL sees and the shapes the renderer intersects are built from the same roots.
#pragma once

#include <cmath>

namespace povtrace {

// Roots of c[0]t² + c[1]t + c[2] (the linear equation's root when c[0] = 0, none when c[1] is 0 too). As POV-Ray
// does, a discriminant within ±1e-10 (SMALL_ENOUGH) after making the polynomial monic counts as a double root,
// returned once. Returns the number of roots: the one of larger magnitude first, computed without cancellation,
// then the other from their product.
inline int quadratic_roots(const double c[3], double roots[2]) {
  constexpr double kSmallEnough = 1e-10;
  if (c[0] == 0.0) {
    if (c[1] == 0.0) return 0;
    roots[0] = -c[2] / c[1];
    return 1;
  }
  const double b = c[1] / c[0], k = c[2] / c[0];
  const double disc = b * b - 4.0 * k;
  if (disc > -kSmallEnough && disc < kSmallEnough) {
    roots[0] = -0.5 * b;
    return 1;
  }
  if (disc < 0.0) return 0;
  const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
  roots[0] = q;
  roots[1] = k / q;
  return 2;
}

}  // namespace povtrace

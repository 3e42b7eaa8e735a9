// mandel, julia and magnet: escape-time fractals in the complex plane of the pattern's x (real) and y (imaginary),
// as POV-Ray 3.7 evaluates them (pattern.cpp mandel*/julia*/magnet* and the exterior/interior colourings;
// povray-sdl-and-geometry.md §11). The arithmetic keeps POV-Ray's order of operations so that the escape iteration,
// and so the value, is the same to the last bit.
#include <cmath>
#include <cstdint>

#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render::patterns {

namespace {

// The value of an orbit that escaped at iteration `iters` at z = a + bi (POV-Ray's exterior types 0…8).
double exterior(const FractalParams& f, int iters, double a, double b) {
  const double k = f.exterior_factor;
  switch (f.exterior_type) {
    case 0: return k;
    case 1: return static_cast<double>(iters) / static_cast<double>(f.iterations);
    case 2: return a * k;
    case 3: return b * k;
    case 4: return a * a * k;
    case 5: return b * b * k;
    case 6: return std::sqrt(a * a + b * b) * k;
    case 7: {   // iteration count modulo the factor (an unsigned int there), over the factor: 0 … (n−1)/n
      const auto n = static_cast<std::uint32_t>(static_cast<std::int64_t>(k));
      return static_cast<double>(static_cast<std::uint32_t>(iters) % n) / k;
    }
    case 8: {   // modulo factor + 1, over the factor: 0 … 1
      const auto n = static_cast<std::uint32_t>(static_cast<std::int64_t>(1 + k));
      return static_cast<double>(static_cast<std::uint32_t>(iters) % n) / k;
    }
    default: return 0;
  }
}

// The value of an orbit that did not escape: z = a + bi after the last iteration, `mindist2` the smallest |z|² met.
double interior(const FractalParams& f, double a, double b, double mindist2) {
  const double k = f.interior_factor;
  switch (f.interior_type) {
    case 0: return k;
    case 1: return std::sqrt(mindist2) * k;
    case 2: return a * k;
    case 3: return b * k;
    case 4: return a * a * k;
    case 5: return b * b * k;
    case 6: return a * a + b * b * k;   // POV-Ray scales only b² here (its expression lacks parentheses)
    default: return 0;
  }
}

// Signed binomial coefficients: the coefficient of a^(n−k)·b^k in (a + bi)^n, with the sign of i^k folded in
// (negative when k mod 4 is 2 or 3). Row n of Pascal's triangle, computed once per exponent.
struct SignedBinomials {
  int row[34][34] = {};
  SignedBinomials() {
    for (int n = 0; n <= 33; ++n) {
      row[n][0] = row[n][n] = 1;
      for (int k = 1; k < n; ++k) row[n][k] = row[n - 1][k - 1] + row[n - 1][k];
    }
    for (int n = 0; n <= 33; ++n)
      for (int k = 0; k <= n; ++k)
        if (k & 2) row[n][k] = -row[n][k];
  }
};
const SignedBinomials& binomials() {
  static const SignedBinomials table;
  return table;
}

// z ← z^n + c for n > 4, expanded by the binomial theorem with pow() on each term (POV-Ray's mandelx/juliax).
void power_step(double& a, double& b, int n, double cr, double ci) {
  const int* c = binomials().row[n];
  double new_a = std::pow(a, n);
  for (int k = 2; k <= n; k += 2) new_a += c[k] * std::pow(a, n - k) * std::pow(b, k);
  double new_b = 0;
  for (int k = 1; k <= n; k += 2) new_b += c[k] * std::pow(a, n - k) * std::pow(b, k);
  a = new_a + cr;
  b = new_b + ci;
}

// mandel (c = the point, z starts at the point) and julia (c = coord): |z|² > 4 escapes.
double mandel_or_julia(const FractalParams& f, Vec3 p) {
  const double cr = f.julia ? f.coord_u : p.x, ci = f.julia ? f.coord_v : p.y;
  double a = p.x, b = p.y;
  double a2 = a * a, b2 = b * b;
  double mindist2 = a2 + b2;
  const int n = f.exponent;
  int col = 0;
  for (; col < f.iterations; ++col) {
    if (n == 2) {
      b = 2.0 * a * b + ci;
      a = a2 - b2 + cr;
    } else if (n == 3) {
      b = 3.0 * a2 * b - b2 * b + ci;
      a = a2 * a - 3.0 * a * b2 + cr;
    } else if (n == 4) {
      b = 4.0 * (a2 * a * b - a * b2 * b) + ci;
      a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
    } else {
      power_step(a, b, n, cr, ci);
    }
    double dist2;
    if (n <= 4) {
      a2 = a * a;
      b2 = b * b;
      dist2 = a2 + b2;
    } else {
      dist2 = a * a + b * b;
    }
    if (dist2 < mindist2) mindist2 = dist2;
    if (dist2 > 4.0) return exterior(f, col, a, b);
  }
  return interior(f, a, b, mindist2);
}

// magnet 1 and 2: z ← ((z² + c − 1) / (2z + c − 2))² and its cubic counterpart; |z|² > 10⁴ or z within 10⁻² of 1
// escapes. The mandel form starts z at 0 (and the smallest |z|² at 10⁴), the julia form at the point.
double magnet(const FractalParams& f, Vec3 p) {
  const double cr = f.julia ? f.coord_u : p.x, ci = f.julia ? f.coord_v : p.y;
  double a = f.julia ? p.x : 0.0, b = f.julia ? p.y : 0.0;
  double a2 = a * a, b2 = b * b;
  double mindist2 = f.julia ? a2 + b2 : 10000.0;
  const double c1r = cr - 1, c2r = cr - 2;
  const double c1c2r = c1r * c2r - ci * ci, c1c2i = (c1r + c2r) * ci;
  int col = 0;
  for (; col < f.iterations; ++col) {
    double t1r, t1i, t2r, t2i;
    if (f.magnet == 1) {
      t1r = a2 - b2 + cr - 1;
      t1i = 2 * a * b + ci;
      t2r = 2 * a + cr - 2;
      t2i = 2 * b + ci;
    } else {
      t1r = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + c1c2r;
      t1i = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + c1c2i;
      t2r = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + c1c2r + 1;
      t2i = 6 * a * b + 3 * (a * ci + b * c2r) + c1c2i;
    }
    const double d = t2r * t2r + t2i * t2i;
    a = (t1r * t2r + t1i * t2i) / d;
    b = (t1i * t2r - t1r * t2i) / d;
    const double bb = b * b;
    b = 2 * a * b;
    a = a * a - bb;
    a2 = a * a;
    b2 = b * b;
    const double dist2 = a2 + b2;
    if (dist2 < mindist2) mindist2 = dist2;
    const double am1 = a - 1;
    if (dist2 > 10000.0 || am1 * am1 + b2 < 1 / 10000.0) return exterior(f, col, a, b);
  }
  return interior(f, a, b, mindist2);
}

}  // namespace

double fractal(const FractalParams& f, Vec3 p) { return f.magnet ? magnet(f, p) : mandel_or_julia(f, p); }

}  // namespace povtrace::render::patterns

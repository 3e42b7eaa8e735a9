// Real roots of polynomials up to degree 35 (see polynomial_roots.hpp for the contract and the POV-Ray rules kept).
#include "runtime/polynomial_roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "runtime/quadratic_roots.hpp"

namespace povtrace::poly {

namespace {
constexpr double kSmallEnough = 1e-10;        // POV-Ray's SMALL_ENOUGH: a coefficient this small is zero
constexpr double kDifficultSpread = 1e12;      // POV-Ray's FUDGE_FACTOR1: coefficient spread that needs Sturm

// Value and derivative together.
void evaluate_with_slope(int degree, const double* c, double t, double& value, double& slope) {
  value = c[0];
  slope = 0.0;
  for (int i = 1; i <= degree; ++i) {
    slope = slope * t + value;
    value = value * t + c[i];
  }
}

// Newton steps from `t` while they reduce |p(t)|: the closed forms lose digits to cancellation, a simple root is
// recovered to rounding in one or two steps, and near a double root (slow convergence) nothing is made worse.
double polish(int degree, const double* c, double t) {
  double value = 0, slope = 0;
  evaluate_with_slope(degree, c, t, value, slope);
  for (int k = 0; k < 4 && value != 0.0 && slope != 0.0; ++k) {
    const double next = t - value / slope;
    double next_value = 0, next_slope = 0;
    evaluate_with_slope(degree, c, next, next_value, next_slope);
    if (!(std::abs(next_value) < std::abs(value))) break;
    t = next;
    value = next_value;
    slope = next_slope;
  }
  return t;
}

// ---- Sturm sequences, as POV-Ray's polysolve computes them ----
// POV-Ray's Sturm solver (polysolv.cpp: polysolve, buildsturm, modp, numchanges, sbisect, regula_falsa) stops
// refining a root when the polynomial's value there is small, |p(t)/t| < 1e-12, not when the root is known to
// rounding; on a flat polynomial (a poly of order 5 and up near a tangent, a blob's density) the root it returns is
// off by far more than rounding, and a shadow ray from that point may find the surface again: speckles that are part
// of POV-Ray's image. The arithmetic below is the same sequence of operations, so the same roots come out.
constexpr int kSturmIterations = 50;            // POV-Ray's MAX_ITERATIONS for bisection and false position
constexpr double kRelativeError = 1e-12;        // POV-Ray's RELERROR

// A polynomial with its coefficients lowest power first (c[i] multiplies tⁱ), as POV-Ray stores the sequence: the
// order of the operations decides the last bits of every value, so it is kept.
template <int Capacity>
struct AscendingPoly {
  int degree = 0;
  std::array<double, Capacity + 1> c;
};

template <int Capacity>
double value_at(const AscendingPoly<Capacity>& p, double t) {
  double v = p.c[static_cast<std::size_t>(p.degree)];
  for (int i = p.degree - 1; i >= 0; --i) v = v * t + p.c[static_cast<std::size_t>(i)];
  return v;
}

// Remainder of u / v for v with leading coefficient ±1, into r; returns r's degree (0 for a constant). Quirk kept:
// POV-Ray's remainder has the opposite sign when v's leading coefficient is −1 and the degrees differ by an even
// number (its sign bookkeeping for that case is off by one step); that sign enters the Sturm counts.
template <int Capacity>
int remainder_into(const AscendingPoly<Capacity>& u, const AscendingPoly<Capacity>& v, AscendingPoly<Capacity>& r) {
  r = u;
  const int du = u.degree, dv = v.degree;
  const bool negative_lead = v.c[static_cast<std::size_t>(dv)] < 0.0;
  const double sign = negative_lead ? -1.0 : 1.0;   // dividing by the monic ±v
  for (int k = du - dv; k >= 0; --k) {
    const double q = r.c[static_cast<std::size_t>(dv + k)];
    for (int j = dv + k - 1; j >= k; --j) r.c[static_cast<std::size_t>(j)] -= q * (sign * v.c[static_cast<std::size_t>(j - k)]);
  }
  if (negative_lead && (du - dv) % 2 == 0)
    for (int j = 0; j < dv; ++j) r.c[static_cast<std::size_t>(j)] = -r.c[static_cast<std::size_t>(j)];
  int k = dv - 1;
  while (k >= 0 && std::abs(r.c[static_cast<std::size_t>(k)]) < kSmallEnough) r.c[static_cast<std::size_t>(k--)] = 0.0;
  r.degree = k < 0 ? 0 : k;
  return r.degree;
}

template <int Capacity>
struct SturmSequence {
  std::array<AscendingPoly<Capacity>, Capacity + 1> p;
  int last = 0;   // index of the final (constant) member

  // c: degree + 1 coefficients, highest power first, c[0] != 0.
  SturmSequence(int degree, const double* c) {
    AscendingPoly<Capacity>& f = p[0];
    f.degree = degree;
    for (int i = 0; i <= degree; ++i) f.c[static_cast<std::size_t>(degree - i)] = c[i] / c[0];
    // The derivative, scaled to a leading coefficient of magnitude 1.
    AscendingPoly<Capacity>& d = p[1];
    d.degree = degree - 1;
    const double scale = std::abs(f.c[static_cast<std::size_t>(degree)] * degree);
    for (int i = 1; i <= degree; ++i) d.c[static_cast<std::size_t>(i - 1)] = f.c[static_cast<std::size_t>(i)] * i / scale;
    // Negated remainders, scaled likewise, until one is a constant; that one is only negated.
    int k = 2;
    while (remainder_into(p[static_cast<std::size_t>(k - 2)], p[static_cast<std::size_t>(k - 1)], p[static_cast<std::size_t>(k)]) != 0) {
      AscendingPoly<Capacity>& r = p[static_cast<std::size_t>(k)];
      const double lead = -std::abs(r.c[static_cast<std::size_t>(r.degree)]);
      for (int i = r.degree; i >= 0; --i) r.c[static_cast<std::size_t>(i)] /= lead;
      ++k;
    }
    p[static_cast<std::size_t>(k)].c[0] = -p[static_cast<std::size_t>(k)].c[0];
    last = k;
  }

  // Sign changes along the sequence of values `value(m)`; a zero counts as a change with the member after it.
  template <class Value>
  int changes(Value&& value) const {
    int n = 0;
    double previous = value(p[0]);
    for (int k = 1; k <= last; ++k) {
      const double v = value(p[static_cast<std::size_t>(k)]);
      if (previous == 0.0 || previous * v < 0.0) ++n;
      previous = v;
    }
    return n;
  }
  int sign_changes(double t) const {
    return changes([t](const AscendingPoly<Capacity>& m) { return value_at(m, t); });
  }
  // Distinct roots in (0, ∞), from the constant and leading coefficients.
  int positive_roots() const {
    const int at_zero = changes([](const AscendingPoly<Capacity>& m) { return m.c[0]; });
    const int at_infinity =
        changes([](const AscendingPoly<Capacity>& m) { return m.c[static_cast<std::size_t>(m.degree)]; });
    return at_zero - at_infinity;
  }
};

// POV-Ray's stopping rule for a refined root: a relative step (or, near 0, an absolute one) below 1e-12.
bool small_relative_to(double size, double at) {
  return std::abs(at) > kRelativeError ? std::abs(size / at) < kRelativeError : std::abs(size) < kRelativeError;
}

// False position with POV-Ray's halving rule, on [a, b]; false when the ends do not bracket a sign change or 50
// steps do not reach a small value.
template <int Capacity>
bool false_position(const AscendingPoly<Capacity>& f, double a, double b, double& root) {
  double fa = value_at(f, a), fb = value_at(f, b);
  if (fa * fb > 0.0) return false;
  if (std::abs(fa) < kSmallEnough) return root = a, true;
  if (std::abs(fb) < kSmallEnough) return root = b, true;
  double previous = fa;
  for (int its = 0; its < kSturmIterations; ++its) {
    const double x = (fb * a - fa * b) / (fb - fa);
    const double fx = value_at(f, x);
    if (small_relative_to(fx, x)) return root = x, true;
    const bool halve = previous * fx > 0.0;   // the same sign twice: weigh the kept end half as much
    if ((fa < 0.0) == (fx < 0.0)) {
      a = x;
      fa = fx;
      if (halve) fb /= 2;
    } else {
      b = x;
      fb = fx;
      if (halve) fa /= 2;
    }
    if (std::abs(b - a) < kRelativeError) return root = x, true;
    previous = fx;
  }
  return false;
}

// Roots in [lo, hi] holding changes_lo − changes_hi distinct ones: bisection on the counts until each is alone, then
// false position, or bisection when that fails. 50 halvings at most per stage; what is left then stands for a root.
template <int Capacity>
int bisect(const SturmSequence<Capacity>& s, double lo, double hi, int changes_lo, int changes_hi, double* roots) {
  const bool single = changes_lo - changes_hi == 1;
  if (single && false_position(s.p[0], lo, hi, roots[0])) return 1;
  double mid = lo;
  for (int its = 0; its < kSturmIterations; ++its) {
    mid = (lo + hi) / 2;
    const int changes_mid = s.sign_changes(mid);
    if (changes_mid < changes_hi || changes_mid > changes_lo) return 0;   // counts out of order: rounding
    if (small_relative_to(hi - lo, mid)) return roots[0] = mid, 1;
    const int below = changes_lo - changes_mid, above = changes_mid - changes_hi;
    if (!single && below != 0 && above != 0) {
      const int n = bisect(s, lo, mid, changes_lo, changes_mid, roots);
      return n + bisect(s, mid, hi, changes_mid, changes_hi, roots + n);
    }
    if (below == 0) lo = mid;
    else hi = mid;
  }
  roots[0] = mid;
  return 1;
}

template <int Capacity>
int sturm_roots(int degree, const double* c, double hi, double* roots) {
  const SturmSequence<Capacity> s(degree, c);
  if (s.positive_roots() == 0) return 0;
  const int changes_lo = s.sign_changes(0.0), changes_hi = s.sign_changes(hi);
  if (changes_lo == changes_hi) return 0;
  return bisect(s, 0.0, hi, changes_lo, changes_hi, roots);
}

// A quartic with a coefficient more than 1e12 times smaller than "the biggest" (POV-Ray's difficult_coeffs). Quirk
// kept: POV-Ray keeps the biggest with its sign and replaces it by every later coefficient larger in magnitude than
// that signed value, so after a negative one the next coefficient always takes its place.
bool difficult_coefficients(int degree, const double* c) {
  double biggest = 0.0;
  for (int i = 0; i <= degree; ++i)
    if (std::abs(c[i]) > biggest) biggest = c[i];
  if (biggest == 0.0) return false;
  for (int i = 0; i <= degree; ++i)
    if (c[i] != 0.0 && std::abs(biggest / c[i]) > kDifficultSpread) return true;
  return false;
}
}  // namespace

// One definition shared with the parser (see polynomial_roots.hpp).
int solve_quadratic(const double c[3], double roots[2]) { return povtrace::quadratic_roots(c, roots); }

int solve_cubic(const double c[4], double roots[3]) {
  if (c[0] == 0.0) return solve_quadratic(c + 1, roots);
  const double monic[4] = {1.0, c[1] / c[0], c[2] / c[0], c[3] / c[0]};
  const double a = monic[1], b = monic[2], d = monic[3];
  const double q = (a * a - 3.0 * b) / 9.0;
  const double r = (a * (2.0 * a * a - 9.0 * b) + 27.0 * d) / 54.0;
  const double q3 = q * q * q;
  int n = 0;
  if (r * r < q3) {   // three real roots: the trigonometric form
    const double cos_arg = std::clamp(r / std::sqrt(q3), -1.0, 1.0);
    const double theta = std::acos(cos_arg) / 3.0;
    const double scale = -2.0 * std::sqrt(q);
    for (int k = 0; k < 3; ++k) roots[n++] = scale * std::cos(theta + k * (2.0 * M_PI / 3.0)) - a / 3.0;
  } else {            // one real root (or a triple one): Cardano
    const double big = -std::copysign(std::cbrt(std::abs(r) + std::sqrt(r * r - q3)), r);
    const double small = big != 0.0 ? q / big : 0.0;
    roots[n++] = big + small - a / 3.0;
  }
  for (int k = 0; k < n; ++k) roots[k] = polish(3, monic, roots[k]);
  return n;
}

int solve_cubic_unpolished(const double c[4], double roots[3]) {
  if (c[0] == 0.0) return solve_quadratic(c + 1, roots);
  const double a = c[1] / c[0], b = c[2] / c[0], d = c[3] / c[0];
  const double a2 = a * a;
  const double q = (a2 - 3.0 * b) / 9.0;
  const double r = (a * (a2 - 4.5 * b) + 13.5 * d) / 27.0;   // (2a³ − 9ab + 27d)/54, grouped as POV-Ray has it
  const double q3 = q * q * q, r2 = r * r;
  const double shift = a / 3.0;
  if (q3 - r2 >= 0.0) {   // three real roots (a NaN one, beyond acos's domain by rounding, is dropped by callers)
    const double theta = std::acos(r / std::sqrt(q3)) / 3.0;
    const double scale = -2.0 * std::sqrt(q);
    constexpr double third_turn = 2.0943951023931957, two_thirds_turn = 4.1887902047863910;   // 2π/3, 4π/3
    roots[0] = scale * std::cos(theta) - shift;
    roots[1] = scale * std::cos(theta + third_turn) - shift;
    roots[2] = scale * std::cos(theta + two_thirds_turn) - shift;
    return 3;
  }
  const double s = std::pow(std::sqrt(r2 - q3) + std::fabs(r), 1.0 / 3.0);
  roots[0] = (r < 0 ? 1.0 : -1.0) * (s + q / s) - shift;
  return 1;
}

int solve_quartic(const double c[5], double roots[4]) {
  const double monic[5] = {1.0, c[1] / c[0], c[2] / c[0], c[3] / c[0], c[4] / c[0]};
  const double a = monic[1], b = monic[2], cc = monic[3], d = monic[4];
  // Depressed quartic y⁴ + p y² + q y + r with t = y − a/4.
  const double a2 = a * a;
  const double p = b - 0.375 * a2;
  const double q = cc - 0.5 * a * b + 0.125 * a2 * a;
  const double r = d - 0.25 * a * cc + 0.0625 * a2 * b - 0.01171875 * a2 * a2;
  const double shift = -0.25 * a;
  int n = 0;
  auto add_quadratic = [&](double lin, double con) {   // real roots of y² + lin·y + con, shifted back
    const double disc = lin * lin - 4.0 * con;
    if (disc < 0.0) return;
    const double root = std::sqrt(disc);
    roots[n++] = 0.5 * (-lin - root) + shift;
    roots[n++] = 0.5 * (-lin + root) + shift;
  };
  const double scale = std::max({std::abs(p), std::sqrt(std::abs(r)), 1e-300});
  if (std::abs(q) <= 1e-14 * scale * std::sqrt(scale)) {
    // Biquadratic: z = y² solves z² + p z + r = 0.
    double z[2];
    const double zc[3] = {1.0, p, r};
    const int nz = solve_quadratic(zc, z);
    for (int k = 0; k < nz; ++k) {
      if (z[k] < 0.0) continue;
      const double y = std::sqrt(z[k]);
      roots[n++] = y + shift;
      if (y != 0.0) roots[n++] = -y + shift;
    }
  } else {
    // Ferrari: (y² + p/2 + m)² = (√(2m)·y − q/(2√(2m)))² for the positive root m of the resolvent
    // m³ + p m² + (p²/4 − r) m − q²/8 = 0 (it has one: the cubic is −q²/8 < 0 at m = 0).
    const double resolvent[4] = {1.0, p, 0.25 * p * p - r, -0.125 * q * q};
    double m_roots[3];
    const int nm = solve_cubic(resolvent, m_roots);
    double m = m_roots[0];
    for (int k = 1; k < nm; ++k) m = std::max(m, m_roots[k]);
    if (!(m > 0.0)) return 0;
    const double s = std::sqrt(2.0 * m);
    add_quadratic(s, 0.5 * p + m - q / (2.0 * s));
    add_quadratic(-s, 0.5 * p + m + q / (2.0 * s));
  }
  for (int k = 0; k < n; ++k) roots[k] = polish(4, monic, roots[k]);
  return n;
}

int solve_sturm(int degree, const double* c, double hi, double* roots) {
  if (degree < 1 || degree > max_sturm_degree || c[0] == 0.0) return 0;
  return degree <= max_degree ? sturm_roots<max_degree>(degree, c, hi, roots)
                              : sturm_roots<max_sturm_degree>(degree, c, hi, roots);
}

int solve_polynomial(int degree, const double* c, double* roots, bool sturm, double elimination_tolerance,
                     double sturm_limit) {
  int first = 0;
  while (first < degree && std::abs(c[first]) < kSmallEnough) ++first;
  const int n = degree - first;
  const double* k = c + first;
  const bool eliminate = elimination_tolerance > 0.0 && n >= 3 && k[n - 1] != 0.0 &&
                         std::abs(k[n] / k[n - 1]) < elimination_tolerance;
  switch (n) {
    case 1:
      roots[0] = -k[1] / k[0];
      return 1;
    case 2:
      return solve_quadratic(k, roots);
    case 3:
      if (eliminate) return solve_quadratic(k, roots);
      return sturm ? solve_sturm(3, k, sturm_limit, roots) : solve_cubic_unpolished(k, roots);
    case 4:
      if (eliminate) return sturm ? solve_sturm(3, k, sturm_limit, roots) : solve_cubic_unpolished(k, roots);
      if (sturm || difficult_coefficients(4, k)) return solve_sturm(4, k, sturm_limit, roots);
      return solve_quartic(k, roots);
    default:
      return n > 4 ? solve_sturm(n, k, sturm_limit, roots) : 0;
  }
}

}  // namespace povtrace::poly

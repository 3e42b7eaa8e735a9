// Real roots of polynomials up to degree 6 (see polynomial_roots.hpp for the contract and the POV-Ray rules kept).
#include "runtime/polynomial_roots.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "runtime/quadratic_roots.hpp"

namespace povtrace::poly {

namespace {
constexpr double kSmallEnough = 1e-10;        // POV-Ray's SMALL_ENOUGH: a coefficient this small is zero
constexpr double kDifficultSpread = 1e12;      // POV-Ray's FUDGE_FACTOR1: coefficient spread that needs Sturm
constexpr int kMaxIterations = 100;

// Value of the polynomial (highest degree first) at t, by Horner's rule.
double evaluate(int degree, const double* c, double t) {
  double v = c[0];
  for (int i = 1; i <= degree; ++i) v = v * t + c[i];
  return v;
}

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

// ---- Sturm sequences ----
struct Poly {
  int degree = 0;
  std::array<double, max_degree + 1> c{};   // highest degree first
};

// Remainder of a / b (b's leading coefficient non-zero), with coefficients below kSmallEnough dropped from the top.
Poly remainder(const Poly& a, const Poly& b) {
  std::array<double, max_degree + 1> r = a.c;
  for (int shift = 0; shift <= a.degree - b.degree; ++shift) {
    const double q = r[shift] / b.c[0];
    for (int i = 0; i <= b.degree; ++i) r[shift + i] -= q * b.c[i];
  }
  Poly out;
  const int first = a.degree - b.degree + 1;   // remainder coefficients start here, degree < b.degree
  int lead = first;
  const int last = a.degree;
  while (lead < last && std::abs(r[lead]) < kSmallEnough) ++lead;
  out.degree = last - lead;
  for (int i = 0; i <= out.degree; ++i) out.c[i] = r[lead + i];
  if (out.degree == 0 && std::abs(out.c[0]) < kSmallEnough) out.c[0] = 0.0;
  return out;
}

// Scales p so that its leading coefficient has magnitude 1 (sign kept).
void normalise(Poly& p) {
  const double lead = std::abs(p.c[0]);
  if (lead == 0.0) return;
  for (int i = 0; i <= p.degree; ++i) p.c[i] /= lead;
}

struct SturmSequence {
  std::array<Poly, max_degree + 1> p;
  int count = 0;

  SturmSequence(int degree, const double* c) {
    Poly& p0 = p[0];
    p0.degree = degree;
    for (int i = 0; i <= degree; ++i) p0.c[i] = c[i];
    normalise(p0);
    Poly& p1 = p[1];
    p1.degree = degree - 1;
    for (int i = 0; i < degree; ++i) p1.c[i] = p0.c[i] * (degree - i);
    normalise(p1);
    count = 2;
    while (p[count - 1].degree > 0 && count <= max_degree) {
      Poly r = remainder(p[count - 2], p[count - 1]);
      if (r.degree == 0 && r.c[0] == 0.0) break;   // p has repeated roots: the sequence ends at their gcd
      for (int i = 0; i <= r.degree; ++i) r.c[i] = -r.c[i];
      normalise(r);
      p[count++] = r;
    }
  }

  // Sign changes of the sequence at t, counted as POV-Ray's numchanges does: an exact zero counts as a change with
  // the member after it (so a root exactly at the lower end of a bracket is counted in it, and found there).
  int sign_changes(double t) const {
    int changes = 0;
    double last = evaluate(p[0].degree, p[0].c.data(), t);
    for (int k = 1; k < count; ++k) {
      const double v = evaluate(p[k].degree, p[k].c.data(), t);
      if (last == 0.0 || (v != 0.0 && (v < 0.0) != (last < 0.0))) ++changes;
      last = v;
    }
    return changes;
  }
};

// The one distinct root in [lo, hi] (changes_lo − changes_hi = 1): Illinois false position while the ends bracket
// a sign change, otherwise (an even-multiplicity root) bisection on the Sturm counts.
double refine_single_root(const SturmSequence& s, double lo, double hi, int changes_lo) {
  const Poly& f = s.p[0];
  double f_lo = evaluate(f.degree, f.c.data(), lo), f_hi = evaluate(f.degree, f.c.data(), hi);
  if (f_lo == 0.0) return lo;
  if (f_hi == 0.0) return hi;
  if ((f_lo < 0.0) != (f_hi < 0.0)) {
    int side = 0;
    for (int k = 0; k < kMaxIterations; ++k) {
      const double t = (lo * f_hi - hi * f_lo) / (f_hi - f_lo);
      if (!(t > lo && t < hi)) break;   // no progress possible in this precision
      const double v = evaluate(f.degree, f.c.data(), t);
      if (v == 0.0) return t;
      if ((v < 0.0) == (f_lo < 0.0)) {
        lo = t;
        f_lo = v;
        if (side == -1) f_hi *= 0.5;   // Illinois: the same end kept twice, halve the other's weight
        side = -1;
      } else {
        hi = t;
        f_hi = v;
        if (side == 1) f_lo *= 0.5;
        side = 1;
      }
      if (hi - lo <= 1e-15 * std::max(1.0, std::abs(t))) break;
    }
    // False position can stall on a wide bracket whose far end is huge (a quartic's value at MAX_DISTANCE): each
    // Illinois halving moves it only a little. POV-Ray then bisects (polysolv.cpp sbisect); so do we, on the sign.
    for (int k = 0; k < 4 * kMaxIterations && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++k) {
      const double mid = 0.5 * (lo + hi);
      if (!(mid > lo && mid < hi)) break;
      const double v = evaluate(f.degree, f.c.data(), mid);
      if (v == 0.0) return mid;
      if ((v < 0.0) == (f_lo < 0.0)) lo = mid, f_lo = v;
      else hi = mid, f_hi = v;
    }
    return std::abs(f_lo) < std::abs(f_hi) ? lo : hi;
  }
  for (int k = 0; k < kMaxIterations && hi - lo > 1e-15 * std::max(1.0, std::abs(lo)); ++k) {
    const double mid = 0.5 * (lo + hi);
    if (s.sign_changes(mid) < changes_lo) hi = mid;
    else lo = mid;
  }
  return 0.5 * (lo + hi);
}

// Isolates the distinct roots in [lo, hi] by bisection on the sign-change counts, ascending.
int isolate(const SturmSequence& s, double lo, double hi, int changes_lo, int changes_hi, double* roots, int depth) {
  const int n = changes_lo - changes_hi;
  if (n <= 0) return 0;
  if (n == 1) {
    roots[0] = refine_single_root(s, lo, hi, changes_lo);
    return 1;
  }
  const double mid = 0.5 * (lo + hi);
  if (depth > 200 || !(mid > lo && mid < hi)) {   // roots closer than the precision: one root stands for them
    roots[0] = mid;
    return 1;
  }
  const int changes_mid = s.sign_changes(mid);
  const int below = isolate(s, lo, mid, changes_lo, changes_mid, roots, depth + 1);
  return below + isolate(s, mid, hi, changes_mid, changes_hi, roots + below, depth + 1);
}

// A quartic whose largest coefficient exceeds a non-zero one by more than 1e12 (POV-Ray's difficult_coeffs).
bool difficult_coefficients(int degree, const double* c) {
  double biggest = 0.0;
  for (int i = 0; i <= degree; ++i) biggest = std::max(biggest, std::abs(c[i]));
  if (biggest == 0.0) return false;
  for (int i = 0; i <= degree; ++i)
    if (c[i] != 0.0 && biggest / std::abs(c[i]) > kDifficultSpread) return true;
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

int solve_sturm(int degree, const double* c, double lo, double hi, double* roots) {
  if (degree < 1 || c[0] == 0.0) return 0;
  const SturmSequence s(degree, c);
  return isolate(s, lo, hi, s.sign_changes(lo), s.sign_changes(hi), roots, 0);
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
      return sturm ? solve_sturm(3, k, 0.0, sturm_limit, roots) : solve_cubic_unpolished(k, roots);
    case 4:
      if (eliminate) return sturm ? solve_sturm(3, k, 0.0, sturm_limit, roots) : solve_cubic_unpolished(k, roots);
      if (sturm || difficult_coefficients(4, k)) return solve_sturm(4, k, 0.0, sturm_limit, roots);
      return solve_quartic(k, roots);
    default:
      return n > 4 ? solve_sturm(n, k, 0.0, sturm_limit, roots) : 0;
  }
}

}  // namespace povtrace::poly

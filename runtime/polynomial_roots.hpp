// Real roots of polynomials of degree ≤ 35 (closed forms up to 4, Sturm sequences above), for the shapes POV-Ray
// solves as polynomials (torus, poly, blob, lathe, prism, sor). Coefficients are given highest degree first:
// c[0]·tⁿ + c[1]·tⁿ⁻¹ + … + c[n].
//
// Two solvers, as POV-Ray 3.7 has (source/backend/math/polysolv.cpp, 3.7-stable, read for the behaviour only):
// - closed forms (quadratic, Cardano/trigonometric cubic, Ferrari quartic), each root then polished by Newton's
//   method on the original polynomial, so that the result is accurate to rounding wherever the root is simple;
// - Sturm-sequence isolation in [0, MAX_DISTANCE] with bisection and false position, computed as POV-Ray's
//   polysolve computes it: slower, but it finds every distinct root there. POV-Ray uses it with `sturm`, by itself
//   when a quartic's coefficients span more than 12 orders of magnitude, and for every degree above 4.
// solve_polynomial picks between them with POV-Ray's rules (see there).
#pragma once

namespace povtrace::poly {

inline constexpr int max_degree = 6;          // a lathe's cubic profile gives sextics
inline constexpr int max_sturm_degree = 35;   // a poly's highest order (POV-Ray's MAX_ORDER)

// Roots of c[0]t² + c[1]t + c[2] (a linear equation when c[0] = 0). A discriminant within ±1e-10 (after making
// the polynomial monic) counts as a double root, returned once, as POV-Ray does. Returns the number of roots.
// It is runtime/quadratic_roots.hpp's quadratic_roots, which the parser's lathe, prism and sor boxes use too.
int solve_quadratic(const double c[3], double roots[2]);
// Real roots of a cubic (a quadratic when c[0] = 0); three roots when the discriminant says so, repeated roots
// repeated. Returns the number of roots.
int solve_cubic(const double c[4], double roots[3]);
// The same closed forms evaluated exactly as POV-Ray's solve_cubic does, without polishing: its roots carry the
// rounding error of the formulas, which decides whether a ray leaving a surface finds it again just beyond the
// depth tolerance (visible in POV-Ray's images of sor and prism surfaces). A discriminant Q³ − R² ≥ 0 gives three
// roots (NaN when rounding takes R/√Q³ past 1); otherwise one. solve_polynomial uses this one for cubics.
int solve_cubic_unpolished(const double c[4], double roots[3]);
// Real roots of a quartic with c[0] != 0 by Ferrari's method, polished. Returns the number of roots (unsorted).
int solve_quartic(const double c[5], double roots[4]);
// The real roots in [0, hi] of the degree-`degree` (≤ max_sturm_degree) polynomial, by POV-Ray's Sturm solver
// (polysolve): Sturm-sequence bisection to isolate each root, then false position stopped at |p(t)/t| < 1e-12, or
// 50 bisections when that fails; a cluster that 50 halvings cannot separate comes back as one root. Its results,
// speckles included, are POV-Ray's: the roots are accurate to the polynomial's flatness, not to rounding. Ascending.
int solve_sturm(int degree, const double* c, double hi, double* roots);

// POV-Ray's Solve_Polynomial: leading coefficients below 1e-10 in magnitude are dropped (the real degree is
// lower); for degrees 3 and 4, when |c[n] / c[n−1]| < `elimination_tolerance` the constant term is taken as zero
// and the root t ≈ 0 removed (a ray starting on the surface does not find it again); a quartic whose coefficients
// span more than 1e12 is solved with Sturm sequences as if `sturm` were given, and so is every polynomial of degree
// 5 to 35 (POV-Ray's polysolve; the order reduction it tries there is overwritten, so none is done). With Sturm
// sequences only roots in
// [0, sturm_limit] are found (POV-Ray: [0, MAX_DISTANCE]); the closed forms return every real root. Roots are
// unsorted. Returns their number.
int solve_polynomial(int degree, const double* c, double* roots, bool sturm, double elimination_tolerance,
                     double sturm_limit);

}  // namespace povtrace::poly

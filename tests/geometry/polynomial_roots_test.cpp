// The polynomial solvers: quartics built from known roots (simple, clustered, double, of very different sizes),
// the closed forms against Sturm sequences, and POV-Ray's switching rules in solve_polynomial.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "runtime/polynomial_roots.hpp"

namespace {

using namespace povtrace::poly;

// Coefficients (highest first) of lead · Π (t − rᵢ).
std::vector<double> from_roots(const std::vector<double>& roots, double lead = 1.0) {
  std::vector<double> c{lead};
  for (double r : roots) {
    c.push_back(0.0);
    for (std::size_t i = c.size() - 1; i > 0; --i) c[i] -= r * c[i - 1];
  }
  return c;
}

std::vector<double> sorted(const double* r, int n) {
  std::vector<double> v(r, r + n);
  std::sort(v.begin(), v.end());
  return v;
}

TEST(PolynomialRoots, QuadraticIsStableForVeryDifferentRoots) {
  const auto c = from_roots({1e-8, 1e4});
  double r[2];
  ASSERT_EQ(solve_quadratic(c.data(), r), 2);
  const auto v = sorted(r, 2);
  EXPECT_NEAR(v[0], 1e-8, 1e-22);
  EXPECT_NEAR(v[1], 1e4, 1e-10);
}

TEST(PolynomialRoots, QuadraticDoubleRootAndNone) {
  double r[2];
  const double dbl[3] = {1, -2, 1};
  ASSERT_EQ(solve_quadratic(dbl, r), 1);
  EXPECT_EQ(r[0], 1.0);
  const double none[3] = {1, 0, 1};
  EXPECT_EQ(solve_quadratic(none, r), 0);
  const double linear[3] = {0, 2, -1};
  ASSERT_EQ(solve_quadratic(linear, r), 1);
  EXPECT_EQ(r[0], 0.5);
}

TEST(PolynomialRoots, CubicThreeAndOneRealRoots) {
  double r[3];
  auto c = from_roots({-2, 0.5, 3});
  ASSERT_EQ(solve_cubic(c.data(), r), 3);
  auto v = sorted(r, 3);
  EXPECT_NEAR(v[0], -2, 1e-14);
  EXPECT_NEAR(v[1], 0.5, 1e-14);
  EXPECT_NEAR(v[2], 3, 1e-14);
  const double one[4] = {2, 0, 2, -4};   // 2(t − 1)(t² + t + 2)
  ASSERT_EQ(solve_cubic(one, r), 1);
  EXPECT_NEAR(r[0], 1, 1e-14);
}

TEST(PolynomialRoots, RandomQuarticsWithFourRealRoots) {
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> root(-10, 10), lead(0.1, 10);
  for (int k = 0; k < 2000; ++k) {
    std::vector<double> roots{root(rng), root(rng), root(rng), root(rng)};
    std::sort(roots.begin(), roots.end());
    if (roots[1] - roots[0] < 1e-2 || roots[2] - roots[1] < 1e-2 || roots[3] - roots[2] < 1e-2) continue;
    const auto c = from_roots(roots, lead(rng));
    double r[4];
    ASSERT_EQ(solve_quartic(c.data(), r), 4) << k;
    const auto v = sorted(r, 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(v[i], roots[i], 1e-9 * (1 + std::abs(roots[i]))) << k;
    // Sturm: the roots in [0, 1e7] only, each where POV-Ray's false position stops (|p(t)/t| < 1e-12 for the monic
    // p) or where 50 bisections leave it (within 9e-9) when false position does not converge in 50 steps.
    std::vector<double> positive;
    for (double x : roots)
      if (x >= 0.0) positive.push_back(x);
    double s[4];
    ASSERT_EQ(solve_sturm(4, c.data(), 1e7, s), static_cast<int>(positive.size())) << k;
    for (std::size_t i = 0; i < positive.size(); ++i) EXPECT_NEAR(s[i], positive[i], 1e-6 * (1 + positive[i])) << k;
  }
}

TEST(PolynomialRoots, QuarticWithTwoRealRootsAndAComplexPair) {
  // (t − 1)(t + 3)(t² + 2t + 5)
  const double c[5] = {1, 4, 6, 4, -15};
  double r[4];
  ASSERT_EQ(solve_quartic(c, r), 2);
  const auto v = sorted(r, 2);
  EXPECT_NEAR(v[0], -3, 1e-13);
  EXPECT_NEAR(v[1], 1, 1e-13);
  double s[4];
  ASSERT_EQ(solve_sturm(4, c, 1e7, s), 1);   // only the positive one in [0, 1e7]
  EXPECT_NEAR(s[0], 1, 1e-8);                // false position stalls, 50 bisections of [0, 1e7] find it
}

TEST(PolynomialRoots, ClusteredRootsAreSeparatedBySturm) {
  const auto c = from_roots({2, 2 + 1e-5, 5, 5 + 2e-5});
  double s[4];
  ASSERT_EQ(solve_sturm(4, c.data(), 1e7, s), 4);
  // Each isolated, then refined as POV-Ray refines: to |p(t)/t| < 1e-12, here within 3e-8 of the root.
  EXPECT_NEAR(s[0], 2, 3e-8);
  EXPECT_NEAR(s[1], 2 + 1e-5, 3e-8);
  EXPECT_NEAR(s[2], 5, 3e-8);
  EXPECT_NEAR(s[3], 5 + 2e-5, 3e-8);
  double r[4];
  ASSERT_EQ(solve_quartic(c.data(), r), 4);
  const auto v = sorted(r, 4);
  EXPECT_NEAR(v[0], 2, 1e-6);
  EXPECT_NEAR(v[3], 5 + 2e-5, 1e-6);
}

TEST(PolynomialRoots, DoubleRootsAreFoundByBoth) {
  const auto c = from_roots({1, 1, 4, 6});
  double s[4];
  const int n = solve_sturm(4, c.data(), 1e7, s);
  ASSERT_EQ(n, 3);   // distinct roots
  EXPECT_NEAR(s[0], 1, 1e-5);   // a double root: false position cannot bracket it, 50 bisections of [0, 1e7] do
  EXPECT_NEAR(s[1], 4, 1e-12);
  double r[4];
  const int m = solve_quartic(c.data(), r);
  ASSERT_GE(m, 2);
  const auto v = sorted(r, m);
  EXPECT_NEAR(v.back(), 6, 1e-12);
}

TEST(PolynomialRoots, SolvePolynomialDropsTheRootAtZero) {
  // Roots 1e-6, 2, 3, 4: |c4 / c3| ≈ 1e-6 / 1 < 1e-4, so the constant is taken as 0 and the cubic solved.
  const auto c = from_roots({1e-6, 2, 3, 4});
  double r[4];
  for (bool sturm : {false, true}) {
    const int n = solve_polynomial(4, c.data(), r, sturm, 1e-4, 1e7);
    ASSERT_EQ(n, 3);
    const auto v = sorted(r, n);
    EXPECT_NEAR(v[0], 2, 1e-5);
    EXPECT_NEAR(v[2], 4, 1e-5);
  }
  // Without the tolerance all four are found.
  EXPECT_EQ(solve_polynomial(4, c.data(), r, false, 0.0, 1e7), 4);
}

TEST(PolynomialRoots, SolvePolynomialLowersTheDegreeOfTinyLeadingCoefficients) {
  const double c[5] = {1e-12, 0, 1, -3, 2};   // effectively (t − 1)(t − 2)
  double r[4];
  ASSERT_EQ(solve_polynomial(4, c, r, false, 0.0, 1e7), 2);
  const auto v = sorted(r, 2);
  EXPECT_NEAR(v[0], 1, 1e-14);
  EXPECT_NEAR(v[1], 2, 1e-14);
}

TEST(PolynomialRoots, DifficultCoefficientsUseSturmAndStillFindTheRoots) {
  // Coefficients spanning more than 1e12: roots 1e-3, 2e-3, 1e3, 2e3.
  const auto c = from_roots({1e-3, 2e-3, 1e3, 2e3});
  double r[4];
  const int n = solve_polynomial(4, c.data(), r, false, 0.0, 1e7);
  ASSERT_EQ(n, 4);
  const auto v = sorted(r, 4);
  EXPECT_NEAR(v[0], 1e-3, 1e-12);
  EXPECT_NEAR(v[1], 2e-3, 1e-12);
  EXPECT_NEAR(v[2], 1e3, 1e-7);
  EXPECT_NEAR(v[3], 2e3, 1e-7);
}

// A blob's density quartic that stays just below its threshold on [0, 1]: its one root in [0, MAX_DISTANCE] is
// beyond 1. The bracket [0, 1e7] has a far end of 1e29, where false position stalls for its 50 steps; POV-Ray then
// bisects [0, 1e7] 50 times and returns the midpoint it has reached, 1e7 / 2⁵⁰ ≈ 9e-9 from the root at most.
TEST(PolynomialRoots, SturmFallsBackToFiftyBisectionsOnAWideBracket) {
  const double c[5] = {10.390287296376723, -20.78057459275345, 10.390287296376675, 5.1304091351867559e-14, -0.65};
  double r[4];
  ASSERT_EQ(solve_sturm(4, c, 1e7, r), 1);
  EXPECT_NEAR(r[0], 1.2071893813, 1e7 / std::pow(2.0, 50));
  // The midpoint of the 50th bracket: a multiple of 1e7 / 2⁵¹.
  const double step = 1e7 / std::pow(2.0, 51);
  EXPECT_EQ(std::fmod(r[0], step), 0.0);
}

TEST(PolynomialRoots, SexticsAreSolvedBySturmInZeroToTheLimit) {
  // Degrees 5 and 6 (a lathe's cubic profile): Sturm sequences whether or not `sturm` is asked for, so only roots
  // in [0, sturm_limit] come back (POV-Ray's polysolve brackets [0, MAX_DISTANCE]).
  std::mt19937 rng(66);
  std::uniform_real_distribution<double> root(-1.0, 2.0);
  for (int k = 0; k < 200; ++k) {
    std::vector<double> roots;
    for (int i = 0; i < 6; ++i) roots.push_back(root(rng));
    std::sort(roots.begin(), roots.end());
    bool separated = true;
    for (int i = 0; i + 1 < 6; ++i) separated = separated && roots[i + 1] - roots[i] > 1e-3;
    if (!separated) continue;
    const auto c = from_roots(roots, 0.5 + k % 3);
    double r[6];
    const int n = solve_polynomial(6, c.data(), r, false, 0.0, 1e7);
    std::vector<double> expected;
    for (double x : roots)
      if (x >= 0.0) expected.push_back(x);
    ASSERT_EQ(n, static_cast<int>(expected.size())) << "sextic " << k;
    const auto found = sorted(r, n);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(found[i], expected[i], 1e-6) << "sextic " << k;
  }
  const auto quintic = from_roots({0.25, 0.5, 3, -1, -2});
  double r[5];
  EXPECT_EQ(sorted(r, solve_polynomial(5, quintic.data(), r, false, 0.0, 1e7)), (std::vector<double>{0.25, 0.5, 3}));
}

TEST(PolynomialRoots, SturmCountsARootAtTheLowerEndAndTheRootsAboveIt) {
  // A ray starting exactly on a surface: p(0) = 0. POV-Ray's numchanges counts the zero as a sign change, so the
  // bracket [0, MAX_DISTANCE] holds both the root at 0 and the next one, which must still be found.
  const auto c = from_roots({-91.7, 0.0, 0.876}, -0.0099);
  double r[3];
  const auto found = sorted(r, solve_sturm(3, c.data(), 1e7, r));
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0], 0.0);
  EXPECT_NEAR(found[1], 0.876, 1e-12);
}

TEST(PolynomialRoots, HighDegreesUpToThirtyFiveAreSolvedBySturm) {
  // A poly of order up to 35 (POV-Ray's MAX_ORDER) reaches the solver as a polynomial of that degree.
  for (int degree : {7, 10, 16, 24}) {
    std::vector<double> roots;
    for (int i = 0; i < degree; ++i) roots.push_back(i % 3 == 0 ? -0.5 - 0.1 * i : 0.25 + 0.05 * i);
    const auto c = from_roots(roots);
    std::vector<double> expected;
    for (double x : roots)
      if (x >= 0.0) expected.push_back(x);
    std::sort(expected.begin(), expected.end());
    double r[max_sturm_degree];
    const int n = solve_polynomial(degree, c.data(), r, false, 0.0, 1e7);
    ASSERT_EQ(n, static_cast<int>(expected.size())) << degree;
    const auto found = sorted(r, n);
    for (int i = 0; i < n; ++i) EXPECT_NEAR(found[i], expected[i], 1e-6) << degree << " root " << i;
  }
  double r[max_sturm_degree];
  // t³⁵ − 2: the one real root 2^(1/35) (the product form of 35 roots is too ill-conditioned to check against).
  std::vector<double> order35(36, 0.0);
  order35[0] = 1;
  order35[35] = -2;
  ASSERT_EQ(solve_polynomial(35, order35.data(), r, false, 0.0, 1e7), 1);
  EXPECT_NEAR(r[0], std::pow(2.0, 1.0 / 35.0), 1e-8);
  const std::vector<double> c(37, 1.0);
  EXPECT_EQ(solve_sturm(36, c.data(), 1e7, r), 0);   // beyond MAX_ORDER: nothing
}

TEST(PolynomialRoots, SturmStopsWhereThePolynomialIsSmallNotWhereTheRootIs) {
  // (t − 1)³ (t − 5): the triple root is one distinct root; around it p is flat (p ≈ −4 (t − 1)³), so false
  // position stops as soon as |p(t)/t| < 1e-12, about 6e-5 from the root: the looseness behind POV-Ray's speckles.
  const auto c = from_roots({1, 1, 1, 5});
  double r[4];
  ASSERT_EQ(solve_sturm(4, c.data(), 1e7, r), 2);
  const auto found = sorted(r, 2);
  EXPECT_GT(std::abs(found[0] - 1.0), 1e-6);
  EXPECT_LT(std::abs(found[0] - 1.0), 1e-3);
  const double t = found[0];
  const double value = (((c[0] * t + c[1]) * t + c[2]) * t + c[3]) * t + c[4];
  EXPECT_LT(std::abs(value / t), 1e-12);
  EXPECT_NEAR(found[1], 5.0, 1e-9);
}

TEST(PolynomialRoots, DifficultCoefficientsKeepPovRaysSignedBiggest) {
  // t⁴ − 5t³ + 3e-12 t² − t − 1: by magnitude 3e-12 is 1.7e12 times smaller than 5, a "difficult" quartic. But
  // POV-Ray's difficult_coeffs keeps the biggest with its sign: after −5 the next coefficient replaces it (|3e-12| >
  // −5), then −1 does (1 > 3e-12), and 3e-12 is only 3.3e11 times smaller than that: not difficult, so Ferrari's
  // method solves it and returns the negative root in (−1, 0) with the positive one in (5, 6); Sturm (asked for)
  // returns only the positive one.
  const double c[5] = {1, -5, 3e-12, -1, -1};
  double r[4];
  const auto closed = sorted(r, solve_polynomial(4, c, r, false, 0.0, 1e7));
  ASSERT_EQ(closed.size(), 2u);
  EXPECT_LT(closed[0], 0.0);
  EXPECT_GT(closed[1], 5.0);
  const auto sturm = sorted(r, solve_polynomial(4, c, r, true, 0.0, 1e7));
  ASSERT_EQ(sturm.size(), 1u);
  EXPECT_NEAR(sturm[0], closed[1], 2e-8);   // Sturm's root is POV-Ray's, within 9e-9
}

}  // namespace

// Polynomial surfaces (poly.cpp) against independent answers: a quartic written as the torus equation agrees with the
// torus primitive on seeded random rays (hit depths, normals, inside), a poly of order 2 written as a sphere agrees
// with the sphere primitive, the term order of POV-Ray's coefficient vector, the quartic reduced to a cubic, and the
// 1e-4 object-space depth tolerance.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quadric_kit.hpp"
#include "renderer/shapes/poly_shape.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

// Index of the term xⁱyʲzᵏ in POV-Ray's order for the given order.
int term_index(int order, int xi, int yj, int zk) {
  int term = 0;
  for (int i = order; i >= 0; --i)
    for (int j = order - i; j >= 0; --j)
      for (int k = order - (i + j); k >= 0; --k) {
        if (i == xi && j == yj && k == zk) return term;
        ++term;
      }
  return -1;
}

Primitive poly_of(int order, const std::vector<std::pair<std::array<int, 3>, double>>& terms, bool sturm = false,
                  const Matrix& m = Matrix::identity()) {
  auto c = std::make_shared<std::vector<double>>((order + 1) * (order + 2) * (order + 3) / 6, 0.0);
  for (const auto& [e, v] : terms) (*c)[static_cast<std::size_t>(term_index(order, e[0], e[1], e[2]))] += v;
  Poly p;
  p.order = order;
  p.coefficients = c;
  p.sturm = sturm;
  p.object_from_world = m.inverse();   // what the parser's transforms compose
  return make_poly(p, m);
}

// (x² + y² + z² + R² − r²)² − 4R²(x² + z²): the torus around y.
Primitive quartic_torus(double R, double r, bool sturm) {
  const double k = R * R - r * r;
  return poly_of(4, {{{4, 0, 0}, 1}, {{0, 4, 0}, 1}, {{0, 0, 4}, 1},
                     {{2, 2, 0}, 2}, {{2, 0, 2}, 2}, {{0, 2, 2}, 2},
                     {{2, 0, 0}, 2 * k - 4 * R * R}, {{0, 2, 0}, 2 * k}, {{0, 0, 2}, 2 * k - 4 * R * R},
                     {{0, 0, 0}, k * k}},
                 sturm);
}

TEST(Poly, TermOrderFollowsPovRay) {
  EXPECT_EQ(term_index(4, 4, 0, 0), 0);
  EXPECT_EQ(term_index(4, 0, 4, 0), 20);
  EXPECT_EQ(term_index(4, 0, 0, 4), 30);
  EXPECT_EQ(term_index(4, 0, 0, 0), 34);
  EXPECT_EQ(term_index(2, 0, 0, 0), 9);
}

TEST(Poly, OrderTwoSphereMatchesTheSpherePrimitive) {
  const Primitive p = poly_of(2, {{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}, {{0, 0, 0}, -4}});
  const Primitive s = sphere({0, 0, 0}, 2);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 o{u(rng) * 6, u(rng) * 6, u(rng) * 6};
    const Vec3 aim{u(rng) * 2.5, u(rng) * 2.5, u(rng) * 2.5};   // mostly through the sphere, some past it
    const Ray r{o, normalize(aim - o)};
    const Intersections a = intersect_all(p, r), b = intersect_all(s, r);
    // The sphere drops a root within 1e-6, the poly within 1e-4 of the origin: compare beyond that.
    std::vector<double> ta, tb;
    for (int i = 0; i < a.count; ++i) if (a.t[i] > 1e-3) ta.push_back(a.t[i]);
    for (int i = 0; i < b.count; ++i) if (b.t[i] > 1e-3) tb.push_back(b.t[i]);
    ASSERT_EQ(ta.size(), tb.size()) << k;
    for (std::size_t i = 0; i < ta.size(); ++i) {
      EXPECT_NEAR(ta[i], tb[i], 1e-9) << k;
      const Vec3 at = r.origin + r.direction * ta[i];
      const Vec3 n = surface_normal(p, at), m = surface_normal(s, at);
      EXPECT_NEAR(dot(n, m), 1.0, 1e-9) << k;
      ++hits;
    }
    EXPECT_EQ(inside(p, o), inside(s, o) || dot(o, o) - 4 < 1e-4) << k;
  }
  EXPECT_GT(hits, 2000);
}

TEST(Poly, QuarticTorusMatchesTheTorusPrimitive) {
  for (bool sturm : {false, true}) {
    const Primitive q = quartic_torus(2, 0.5, sturm);
    const Primitive t = make_torus(Torus{2, 0.5, false}, Matrix::identity());
    std::mt19937 rng(sturm ? 11 : 12);
    std::uniform_real_distribution<double> u(-1, 1);
    int compared = 0;
    for (int k = 0; k < 2000; ++k) {
      const Vec3 o{u(rng) * 5, u(rng) * 2, u(rng) * 5};
      const Ray r{o, normalize(Vec3{u(rng), u(rng) * 0.5, u(rng)})};
      const Intersections a = intersect_all(q, r), b = intersect_all(t, r);
      if (a.count != b.count) continue;   // a root within either shape's own depth tolerance of the origin
      for (int i = 0; i < a.count; ++i) {
        EXPECT_NEAR(a.t[i], b.t[i], 1e-6) << k << " sturm " << sturm;
        const Vec3 at = r.origin + r.direction * a.t[i];
        EXPECT_NEAR(dot(surface_normal(q, at), surface_normal(t, at)), 1.0, 1e-6) << k;
      }
      ++compared;
    }
    EXPECT_GT(compared, 1950);
  }
}

TEST(Poly, OcticRoundedCube) {
  // x⁸ + y⁸ + z⁸ − 1 = 0: along each axis the surface is at ±1, along the diagonal at 3^(−1/8).
  const Primitive p = poly_of(8, {{{8, 0, 0}, 1}, {{0, 8, 0}, 1}, {{0, 0, 8}, 1}, {{0, 0, 0}, -1}});
  const Intersections along_x = intersect_all(p, Ray{{-3, 0, 0}, {1, 0, 0}});
  ASSERT_EQ(along_x.count, 2);
  EXPECT_NEAR(along_x.t[0], 2.0, 1e-9);
  EXPECT_NEAR(along_x.t[1], 4.0, 1e-9);
  const Vec3 d = normalize(Vec3{1, 1, 1});
  const Intersections diagonal = intersect_all(p, Ray{d * -5.0, d});
  ASSERT_EQ(diagonal.count, 2);
  const double corner = std::sqrt(3.0) * std::pow(3.0, -1.0 / 8.0);
  EXPECT_NEAR(diagonal.t[0], 5.0 - corner, 1e-9);
  EXPECT_NEAR(diagonal.t[1], 5.0 + corner, 1e-9);
  EXPECT_NEAR(dot(surface_normal(p, d * corner), d), 1.0, 1e-12);   // the gradient, normalised
  EXPECT_TRUE(inside(p, {0.9, 0.9, 0}));
  EXPECT_FALSE(inside(p, {0.95, 0.95, 0.95}));
}

TEST(Poly, QuarticWithoutFourthPowersIsSolvedAsACubic) {
  // z = x³ (a quartic vector with the x³ and z terms only): along x at height z = 1 the surface is at x = 1.
  const Primitive p = poly_of(4, {{{3, 0, 0}, 1}, {{0, 0, 1}, -1}});
  const Intersections xs = intersect_all(p, Ray{{-3, 0, 1}, {1, 0, 0}});
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 4.0, 1e-9);
}

TEST(Poly, RootsCloserThanTheDepthToleranceAreDropped) {
  const Primitive p = poly_of(2, {{{2, 0, 0}, 1}, {{0, 2, 0}, 1}, {{0, 0, 2}, 1}, {{0, 0, 0}, -1}});
  EXPECT_EQ(intersect_all(p, Ray{{0, 0, -1 - 5e-5}, {0, 0, 1}}).count, 1);   // the near root at 5e-5 is gone
  EXPECT_EQ(intersect_all(p, Ray{{0, 0, -1 - 2e-4}, {0, 0, 1}}).count, 2);
}

TEST(Quadric, TransformedQuadricMatchesTheTransformedSphere) {
  // x² + y² + z² − 1 = 0 scaled, rotated and moved: the transforms are folded into the coefficients, and the result
  // must agree with a sphere primitive carrying the same transform (an ellipsoid).
  Matrix m = Matrix::scaling({1.5, 0.5, 0.8}) * Matrix::rotation({20, 35, -10}) * Matrix::translation({1, -2, 3});
  const Primitive q = make_quadric(Quadric{{1, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1}, m);
  const Primitive s = transformed(sphere({0, 0, 0}, 1), m);
  std::mt19937 rng(21);
  std::uniform_real_distribution<double> u(-1, 1);
  int hits = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 o = Vec3{1, -2, 3} + Vec3{u(rng), u(rng), u(rng)} * 5.0;
    const Vec3 aim = Vec3{1, -2, 3} + Vec3{u(rng), u(rng), u(rng)} * 1.2;
    const Ray r{o, normalize(aim - o)};
    const Intersections a = intersect_all(q, r), b = intersect_all(s, r);
    std::vector<double> ta, tb;
    for (int i = 0; i < a.count; ++i) if (a.t[i] > 1e-3) ta.push_back(a.t[i]);
    for (int i = 0; i < b.count; ++i) if (b.t[i] > 1e-3) tb.push_back(b.t[i]);
    ASSERT_EQ(ta.size(), tb.size()) << k;
    for (std::size_t i = 0; i < ta.size(); ++i) {
      EXPECT_NEAR(ta[i], tb[i], 1e-9) << k;
      const Vec3 at = r.origin + r.direction * ta[i];
      EXPECT_NEAR(dot(surface_normal(q, at), surface_normal(s, at)), 1.0, 1e-9) << k;
      ++hits;
    }
    EXPECT_EQ(inside(q, o), inside(s, o)) << k;
  }
  EXPECT_GT(hits, 1500);   // coverage: most of the 2000 rays cross the flattened ellipsoid
}

TEST(Quadric, LinearQuadricIsAPlaneWithItsOwnInsideRule) {
  // y − 1 = 0 (no quadratic terms): one root; the surface itself counts as inside (value <= 0).
  const Primitive q = make_quadric(Quadric{{0, 0, 0}, {0, 0, 0}, {0, 1, 0}, -1}, Matrix::identity());
  const Intersections xs = intersect_all(q, Ray{{0, 5, 0}, {0, -1, 0}});
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 4.0, 1e-12);
  EXPECT_TRUE(inside(q, {0, 1, 0}));
  EXPECT_TRUE(inside(q, {0, 0, 0}));
  EXPECT_FALSE(inside(q, {0, 2, 0}));
}

}  // namespace

// Torus: hand-computed hits along axes, grazing and near-tangent rays, rays from 1e5 away, POV-Ray's inside rule,
// sturm agreeing with the closed form, and seeded random rays against marching on the torus's implicit form.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quadric_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

Primitive torus(double major, double minor, bool sturm = false, const Matrix& m = Matrix::identity()) {
  return make_torus(Torus{major, minor, sturm}, m);
}

// (√(x² + z²) − R)² + y² − r² in object space: negative inside.
double torus_function(double major, double minor, Vec3 q) {
  const double w = std::sqrt(q.x * q.x + q.z * q.z) - major;
  return w * w + q.y * q.y - minor * minor;
}

TEST(Torus, RayThroughTheCentreMeetsFourSurfaces) {
  for (bool sturm : {false, true}) {
    const Primitive t = torus(2, 0.5, sturm);
    const Intersections xs = intersect_all(t, ray({-10, 0, 0}, {1, 0, 0}));
    ASSERT_EQ(xs.count, 4);
    EXPECT_NEAR(xs.t[0], 7.5, 1e-12);
    EXPECT_NEAR(xs.t[1], 8.5, 1e-12);
    EXPECT_NEAR(xs.t[2], 11.5, 1e-12);
    EXPECT_NEAR(xs.t[3], 12.5, 1e-12);
    const Vec3 n = surface_normal(t, {-2.5, 0, 0});
    EXPECT_NEAR(n.x, -1, 1e-12);
    EXPECT_NEAR(surface_normal(t, {-1.5, 0, 0}).x, 1, 1e-12);
    EXPECT_NEAR(surface_normal(t, {0, 0.5, 2}).y, 1, 1e-12);
  }
}

TEST(Torus, HorizontalRaysAtEveryHeightMatchTheAnalyticRoots) {
  // At height y along x (z = 0): |x| = R ± √(r² − y²).
  const double major = 3, minor = 1;
  for (bool sturm : {false, true}) {
    const Primitive t = torus(major, minor, sturm);
    for (double y = -0.999; y < 1; y += 0.037) {
      const double s = std::sqrt(minor * minor - y * y);
      const Intersections xs = intersect_all(t, ray({-20, y, 0}, {1, 0, 0}));
      ASSERT_EQ(xs.count, 4) << "y " << y;
      const double expect[4] = {20 - major - s, 20 - major + s, 20 + major - s, 20 + major + s};
      for (int i = 0; i < 4; ++i) EXPECT_NEAR(xs.t[i], expect[i], 1e-9) << "y " << y << " sturm " << sturm;
    }
  }
}

TEST(Torus, NearTangentRaysOverTheTop) {
  // Just below the top of the tube (y = r − δ) a horizontal ray meets it in two close pairs; just above, nowhere.
  for (bool sturm : {false, true}) {
    const Primitive t = torus(1, 0.25, sturm);
    for (double delta : {1e-3, 1e-4, 1e-5}) {
      const double y = 0.25 - delta, s = std::sqrt(0.25 * 0.25 - y * y);
      const Intersections xs = intersect_all(t, ray({-5, y, 0}, {1, 0, 0}));
      ASSERT_EQ(xs.count, 4) << "delta " << delta << " sturm " << sturm;
      EXPECT_NEAR(xs.t[0], 4 - s, 1e-6 * s + 1e-9);
      EXPECT_NEAR(xs.t[1], 4 + s, 1e-6 * s + 1e-9);
      EXPECT_LT(xs.t[0], xs.t[1]);
      EXPECT_EQ(intersect_all(t, ray({-5, 0.25 + delta, 0}, {1, 0, 0})).count, 0);
    }
  }
}

TEST(Torus, GrazingTheInnerEquatorAndTheOuterSilhouette) {
  const Primitive t = torus(2, 0.5);
  // A ray along z at x = 2.5 − δ (inside the outer silhouette) and x = 2.5 + δ (outside).
  Intersections xs = intersect_all(t, ray({2.5 - 1e-4, 0, -10}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 10 - std::sqrt(2.5 * 2.5 - std::pow(2.5 - 1e-4, 2)), 1e-6);
  EXPECT_EQ(intersect_all(t, ray({2.5 + 1e-4, 0, -10}, {0, 0, 1})).count, 0);
  // Grazing the inner equator from the hole (x = 1.5 − δ): out of the tube into the hole and back, two roots
  // 2·√(1.5² − x²) apart; at x = 1.5 + δ the ray stays in the tube from one side to the other.
  const double x = 1.5 - 1e-4, half = std::sqrt(1.5 * 1.5 - x * x);
  xs = intersect_all(t, ray({x, 0, -10}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 4);
  EXPECT_NEAR(xs.t[1], 10 - half, 1e-8);
  EXPECT_NEAR(xs.t[2], 10 + half, 1e-8);
  EXPECT_EQ(intersect_all(t, ray({1.5 + 1e-4, 0, -10}, {0, 0, 1})).count, 2);
}

TEST(Torus, RaysFromFarAwayKeepTheirPrecision) {
  std::mt19937 rng(11);
  for (bool sturm : {false, true}) {
    const Primitive t = torus(1, 0.3, sturm);
    for (int k = 0; k < 200; ++k) {
      const Vec3 dir = random_unit(rng);
      const Vec3 origin = dir * -1e5;
      // Aim at a point of the tube's centre circle so that the ray surely crosses the tube.
      const double a = 2 * M_PI * k / 200;
      const Vec3 target{std::cos(a), 0, std::sin(a)};
      const Ray r = ray(origin, target - origin);
      const Intersections xs = intersect_all(t, r);
      ASSERT_GE(xs.count, 2) << "ray " << k;
      for (int i = 0; i < xs.count; ++i) {
        const Vec3 p = r.origin + r.direction * xs.t[i];
        EXPECT_NEAR(torus_function(1, 0.3, p), 0.0, 1e-9) << "ray " << k << " root " << i;
      }
    }
  }
}

TEST(Torus, RayStartingOnTheSurfaceDoesNotFindItAgain) {
  // POV-Ray drops the t ≈ 0 root by order reduction (ROOT_TOLERANCE) and DEPTH_TOLERANCE 1e-4.
  const Primitive t = torus(2, 0.5);
  Intersections xs = intersect_all(t, ray({-2.5, 0, 0}, {1, 0, 0}));   // from the outer equator, inwards
  ASSERT_EQ(xs.count, 3);
  EXPECT_NEAR(xs.t[0], 1, 1e-9);
  xs = intersect_all(t, ray({-2.5, 0, 0}, {-1, 0, 0}));                 // outwards: nothing
  EXPECT_EQ(xs.count, 0);
}

TEST(Torus, InsideCountsTheSurface) {
  Primitive t = torus(2, 0.5);
  EXPECT_TRUE(inside(t, {2, 0, 0}));
  EXPECT_TRUE(inside(t, {2.5, 0, 0}));   // on the surface: inside (<=)
  EXPECT_FALSE(inside(t, {0, 0, 0}));
  EXPECT_FALSE(inside(t, {2, 0.6, 0}));
  t.inverse = true;
  EXPECT_FALSE(inside(t, {2.5, 0, 0}));
  EXPECT_TRUE(inside(t, {0, 0, 0}));
}

TEST(Torus, RandomRaysMatchMarchingOnTheImplicitForm) {
  std::mt19937 rng(31337);
  std::uniform_real_distribution<double> pos(-12, 12), big(0.5, 3), u(0, 1);
  int compared = 0, hits = 0;
  for (int k = 0; k < 1500; ++k) {
    const double major = big(rng), minor = major * (0.1 + 0.6 * u(rng));
    const Matrix m = k % 2 ? random_mirroring_transform(rng, 1) : Matrix::identity();
    const Matrix inv = m.inverse();
    const Primitive t = torus(major, minor, k % 3 == 0, m);
    auto member = [&](Vec3 w) { return torus_function(major, minor, inv.point(w)) < 0; };
    const Vec3 origin{pos(rng), pos(rng), pos(rng)};
    const Vec3 target = m.point(random_unit(rng) * major);
    const Ray r = ray(origin, target - origin);
    if (inside(t, origin) || std::abs(torus_function(major, minor, inv.point(origin))) < 1e-3) continue;
    const std::vector<double> ref = crossings(member, r, 0.0, 80.0, 8000);
    const Intersections xs = intersect_all(t, r);
    if (static_cast<int>(ref.size()) != xs.count) continue;   // a grazing ray: a double root either way
    ++compared;
    for (int i = 0; i < xs.count; ++i) {
      EXPECT_NEAR(xs.t[i], ref[i], 1e-7 * (1 + ref[i])) << "ray " << k;
      const Vec3 p = r.origin + r.direction * xs.t[i];
      const Vec3 q = inv.point(p);
      const double e = 1e-6;
      const Vec3 grad{torus_function(major, minor, q + Vec3{e, 0, 0}) - torus_function(major, minor, q - Vec3{e, 0, 0}),
                      torus_function(major, minor, q + Vec3{0, e, 0}) - torus_function(major, minor, q - Vec3{0, e, 0}),
                      torus_function(major, minor, q + Vec3{0, 0, e}) - torus_function(major, minor, q - Vec3{0, 0, e})};
      EXPECT_NEAR(dot(surface_normal(t, p), world_normal(m, grad)), 1.0, 1e-6) << "ray " << k;
    }
    hits += xs.count > 0;
  }
  EXPECT_GT(compared, 1300);
  EXPECT_GT(hits, 500);
}

TEST(Torus, BoundsContainTheTorus) {
  std::mt19937 rng(9);
  for (int k = 0; k < 100; ++k) {
    const Matrix m = random_mirroring_transform(rng, 0);
    const Primitive t = torus(1.5, 0.4, false, m);
    const Bounds b = world_bounds(t);
    for (int j = 0; j < 100; ++j) {
      const double a = 2 * M_PI * j / 100, c = 2 * M_PI * ((j * 7) % 100) / 100;
      const Vec3 q = m.point(Vec3{(1.5 + 0.4 * std::cos(c)) * std::cos(a), 0.4 * std::sin(c),
                                  (1.5 + 0.4 * std::cos(c)) * std::sin(a)});
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(q[i], b.lo[i] - 1e-9);
        EXPECT_LE(q[i], b.hi[i] + 1e-9);
      }
    }
  }
}

}  // namespace

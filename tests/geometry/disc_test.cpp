// Disc: hand-computed hits, the hole, the half-space inside rule, the constant normal, and seeded random rays
// against random transformed discs checked against the analytic plane crossing of the written disc.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quadric_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

Primitive disc(Vec3 c, Vec3 n, double r, double hole = 0, const Matrix& m = Matrix::identity()) {
  return make_disc(Disc{c, normalize(n), r, hole}, m);
}

TEST(Disc, HitInsideTheAnnulusOnly) {
  const Primitive d = disc({0, 1, 0}, {0, 1, 0}, 2, 0.5);
  Intersections xs = intersect_all(d, ray({1, 5, 0}, {0, -1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 4, 1e-12);
  EXPECT_EQ(intersect_all(d, ray({0.3, 5, 0}, {0, -1, 0})).count, 0);   // through the hole
  EXPECT_EQ(intersect_all(d, ray({2.1, 5, 0}, {0, -1, 0})).count, 0);   // outside
  EXPECT_EQ(intersect_all(d, ray({2, 5, 0}, {0, -1, 0})).count, 1);     // the rim is included
  EXPECT_EQ(intersect_all(d, ray({0.5, 5, 0}, {0, -1, 0})).count, 1);   // so is the hole's edge
  EXPECT_EQ(intersect_all(d, ray({1, 5, 0}, {1, 0, 0})).count, 0);      // parallel
  EXPECT_EQ(intersect_all(d, ray({1, 5, 0}, {0, 1, 0})).count, 0);      // away
}

TEST(Disc, NormalIsTheWrittenOneEverywhere) {
  const Primitive d = disc({0, 0, 0}, {1, 1, 0}, 1);
  const Vec3 n = surface_normal(d, {0.1, -0.1, 0.3});
  EXPECT_NEAR(n.x, std::sqrt(0.5), 1e-15);
  EXPECT_NEAR(n.y, std::sqrt(0.5), 1e-15);
}

TEST(Disc, InsideIsTheHalfSpaceBehindTheNormal) {
  Primitive d = disc({0, 1, 0}, {0, 1, 0}, 1);
  EXPECT_TRUE(inside(d, {5, 0, 5}));     // far outside the disc's radius but behind it
  EXPECT_FALSE(inside(d, {0, 1, 0}));    // the plane itself is outside
  EXPECT_FALSE(inside(d, {0, 2, 0}));
  d.inverse = true;
  EXPECT_FALSE(inside(d, {5, 0, 5}));
  EXPECT_TRUE(inside(d, {0, 1, 0}));
}

TEST(Disc, WorldDepthToleranceIsOneMicron) {
  const Primitive d = disc({0, 0, 0}, {0, 1, 0}, 1);
  EXPECT_EQ(intersect_all(d, ray({0, 5e-7, 0}, {0, -1, 0})).count, 0);
  EXPECT_EQ(intersect_all(d, ray({0, 2e-6, 0}, {0, -1, 0})).count, 1);
}

TEST(Disc, RandomRaysMatchThePlaneCrossing) {
  std::mt19937 rng(555);
  std::uniform_real_distribution<double> pos(-10, 10), c(-2, 2), rad(0.5, 3), u(0, 1);
  int hits = 0;
  for (int k = 0; k < 3000; ++k) {
    const Vec3 centre{c(rng), c(rng), c(rng)};
    const Vec3 normal = random_unit(rng);
    const double outer = rad(rng), hole = u(rng) < 0.5 ? 0.0 : outer * u(rng);
    const Matrix m = k % 2 ? random_mirroring_transform(rng, 1) : Matrix::identity();
    const Primitive d = disc(centre, normal, outer, hole, m);
    const Vec3 origin{pos(rng), pos(rng), pos(rng)};
    const Ray r = ray(origin, m.point(centre) + random_unit(rng) * outer - origin);
    // Independent answer in object space: the plane (q − C)·N = 0 along the object-space ray.
    const Matrix inv = m.inverse();
    const Vec3 o = inv.point(r.origin), dir = inv.vector(r.direction);
    const double t = dot(centre - o, normal) / dot(dir, normal);
    const Vec3 q = o + dir * t;
    const double r2 = dot(q - centre, q - centre);
    const bool expect_hit = t > 1e-6 && r2 >= hole * hole && r2 <= outer * outer;
    const bool margin = std::abs(std::sqrt(r2) - outer) < 1e-9 || std::abs(std::sqrt(r2) - hole) < 1e-9;
    if (margin) continue;
    const Intersections xs = intersect_all(d, r);
    ASSERT_EQ(xs.count, expect_hit ? 1 : 0) << "ray " << k;
    if (!expect_hit) continue;
    ++hits;
    EXPECT_NEAR(xs.t[0], t, 1e-9 * (1 + t)) << "ray " << k;
    const Vec3 n = surface_normal(d, r.origin + r.direction * xs.t[0]);
    EXPECT_NEAR(dot(n, world_normal(m, normal)), 1.0, 1e-12);
    // A ray leaving the hit point on either side never meets the flat disc again.
    const Vec3 p = r.origin + r.direction * xs.t[0];
    const Accelerator single(std::vector<Primitive>{d});
    EXPECT_FALSE(single.closest_hit({p, n}, tolerance::min_isect_depth, tolerance::bound_huge).found());
    EXPECT_FALSE(single.closest_hit({p, -n}, tolerance::min_isect_depth, tolerance::bound_huge).found());
  }
  EXPECT_GT(hits, 1000);
}

TEST(Disc, BoundsContainTheDisc) {
  std::mt19937 rng(8);
  for (int k = 0; k < 100; ++k) {
    const Vec3 normal = random_unit(rng);
    const Matrix m = random_transform(rng);
    const Primitive d = disc({0.5, 0, -0.5}, normal, 1.5, 0, m);
    const Bounds b = world_bounds(d);
    const Vec3 t1 = normalize(cross(normal, std::abs(normal.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 t2 = cross(normal, t1);
    for (int j = 0; j < 36; ++j) {
      const double a = j * M_PI / 18;
      const Vec3 q = m.point(Vec3{0.5, 0, -0.5} + (t1 * std::cos(a) + t2 * std::sin(a)) * 1.5);
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(q[i], b.lo[i] - 1e-9);
        EXPECT_LE(q[i], b.hi[i] + 1e-9);
      }
    }
  }
}

}  // namespace

// Sphere intersection, normal, inside and bounds against hand-computed values and an independent world-space solve
// (marching + bisection on the implicit function of the transformed sphere).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "geometry_kit.hpp"
#include "renderer/geometry.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

// Implicit function of the (possibly transformed) sphere at a world point: negative inside.
double implicit(const Primitive& p, Vec3 world) {
  const Vec3 q = p.transformed ? p.object_from_world.point(world) : world;
  const Vec3 d = q - p.a;
  return dot(d, d) - p.radius * p.radius;
}

// World-space roots of the implicit function along the ray in (0, t_end), by marching and bisection.
std::vector<double> march_roots(const Primitive& p, const Ray& r, double t_end, int steps) {
  std::vector<double> roots;
  auto f = [&](double t) { return implicit(p, r.origin + r.direction * t); };
  double t0 = 0, f0 = f(0);
  for (int k = 1; k <= steps; ++k) {
    const double t1 = t_end * k / steps, f1 = f(t1);
    if ((f0 < 0) != (f1 < 0)) {
      double lo = t0, hi = t1;
      const bool lo_negative = f0 < 0;
      for (int it = 0; it < 200 && hi - lo > 0; ++it) {
        const double m = 0.5 * (lo + hi);
        if (m <= lo || m >= hi) break;
        if ((f(m) < 0) == lo_negative) lo = m; else hi = m;
      }
      roots.push_back(0.5 * (lo + hi));
    }
    t0 = t1;
    f0 = f1;
  }
  return roots;
}

TEST(Sphere, AxisRayHitsBothSides) {
  const Primitive s = sphere({0, 0, 5}, 1);
  const Intersections xs = intersect_all(s, ray({0, 0, 0}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_DOUBLE_EQ(xs.t[0], 4.0);
  EXPECT_DOUBLE_EQ(xs.t[1], 6.0);
  const Vec3 n = surface_normal(s, {0, 0, 4});
  EXPECT_DOUBLE_EQ(n.x, 0);
  EXPECT_DOUBLE_EQ(n.y, 0);
  EXPECT_DOUBLE_EQ(n.z, -1);
}

TEST(Sphere, OffAxisHitMatchesPythagoras) {
  // Ray along +z at x = 0.6 through a unit sphere at the origin: z = ±0.8.
  const Primitive s = sphere({0, 0, 0}, 1);
  const Intersections xs = intersect_all(s, ray({0.6, 0, -10}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 9.2, 1e-14);
  EXPECT_NEAR(xs.t[1], 10.8, 1e-14);
  const Vec3 n = surface_normal(s, {0.6, 0, -0.8});
  EXPECT_NEAR(n.x, 0.6, 1e-15);
  EXPECT_NEAR(n.z, -0.8, 1e-15);
}

TEST(Sphere, FromInsideOnlyTheExit) {
  const Primitive s = sphere({1, 2, 3}, 2);
  const Intersections xs = intersect_all(s, ray({1, 2, 3}, {0, 1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_DOUBLE_EQ(xs.t[0], 2.0);
}

TEST(Sphere, BehindOrAwayMisses) {
  const Primitive s = sphere({0, 0, 5}, 1);
  EXPECT_EQ(intersect_all(s, ray({0, 0, 0}, {0, 0, -1})).count, 0);
  EXPECT_EQ(intersect_all(s, ray({0, 0, 0}, {0, 1, 0})).count, 0);
  EXPECT_EQ(intersect_all(s, ray({3, 0, 0}, {0, 0, 1})).count, 0);
}

TEST(Sphere, GrazingRayMisses) {
  const Primitive s = sphere({0, 0, 5}, 1);
  // Exactly tangent: half chord² = 0.
  EXPECT_EQ(intersect_all(s, ray({1, 0, 0}, {0, 0, 1})).count, 0);
  // Half chord² = 5e-11 <= EPSILON: still a miss.
  EXPECT_EQ(intersect_all(s, ray({std::sqrt(1 - 5e-11), 0, 0}, {0, 0, 1})).count, 0);
  // Half chord² = 1e-9 > EPSILON: two nearly equal roots.
  const Intersections xs = intersect_all(s, ray({std::sqrt(1 - 1e-9), 0, 0}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 5.0, 1e-4);
  EXPECT_NEAR(xs.t[1], 5.0, 1e-4);
  EXPECT_LT(xs.t[0], xs.t[1]);
}

TEST(Sphere, DepthToleranceIsStrictAtOneMicron) {
  const Primitive s = sphere({0, 0, 5}, 1);
  // Origin on the surface heading in: the zero root is dropped, the far side kept.
  Intersections xs = intersect_all(s, ray({0, 0, 4}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_DOUBLE_EQ(xs.t[0], 2.0);
  // Origin on the surface heading out: miss (outside-or-on and moving away).
  EXPECT_EQ(intersect_all(s, ray({0, 0, 4}, {0, 0, -1})).count, 0);
  // 5e-7 in front of the surface: dropped; 2e-6 in front: kept.
  xs = intersect_all(s, ray({0, 0, 4 - 5e-7}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 1);
  xs = intersect_all(s, ray({0, 0, 4 - 2e-6}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 2e-6, 1e-12);
}

TEST(Sphere, MaxDistance) {
  // Both roots beyond 1e7: none; a sphere straddling 1e7 keeps only the near root.
  EXPECT_EQ(intersect_all(sphere({0, 0, 1e7 + 10}, 1), ray({0, 0, 0}, {0, 0, 1})).count, 0);
  const Intersections xs = intersect_all(sphere({0, 0, 1e7}, 1), ray({0, 0, 0}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_DOUBLE_EQ(xs.t[0], 1e7 - 1);
}

TEST(Sphere, InsideIsStrictBothWays) {
  Primitive s = sphere({0, 0, 0}, 1);
  EXPECT_TRUE(inside(s, {0, 0, 0}));
  EXPECT_TRUE(inside(s, {0.999999, 0, 0}));
  EXPECT_FALSE(inside(s, {1, 0, 0}));  // on the surface: outside
  EXPECT_FALSE(inside(s, {0, 2, 0}));
  s.inverse = true;
  EXPECT_FALSE(inside(s, {0, 0, 0}));
  EXPECT_FALSE(inside(s, {1, 0, 0}));  // on the surface: outside of the inverse too (POV-Ray's d² > r²)
  EXPECT_TRUE(inside(s, {0, 2, 0}));
}

TEST(Sphere, InsideOfTransformedUsesObjectSpace) {
  Primitive s = transformed(sphere({0, 0, 0}, 1), Matrix::scaling({4, 1, 1}));
  EXPECT_TRUE(inside(s, {3.9, 0, 0}));
  EXPECT_FALSE(inside(s, {0, 1.1, 0}));
  EXPECT_FALSE(inside(s, {4, 0, 0}));
}

TEST(Sphere, ScaledAndTranslatedEllipsoid) {
  // Unit sphere scaled <2,1,1> then moved to z = 10: semi-axis 2 along x.
  const Primitive s = transformed(sphere({0, 0, 0}, 1), Matrix::scaling({2, 1, 1}) * Matrix::translation({0, 0, 10}));
  Intersections xs = intersect_all(s, ray({0, 0, 0}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 9, 1e-12);
  EXPECT_NEAR(xs.t[1], 11, 1e-12);
  xs = intersect_all(s, ray({-10, 0, 10}, {1, 0, 0}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 8, 1e-12);  // world distance, not the object-space 4
  EXPECT_NEAR(xs.t[1], 12, 1e-12);
  Vec3 n = surface_normal(s, {-2, 0, 10});
  EXPECT_NEAR(n.x, -1, 1e-12);
  EXPECT_NEAR(length(n), 1, 1e-14);
  // Off-axis point (2 cos θ, sin θ): the normal of x²/4 + y² = 1 is ∝ (cos θ / 2, sin θ).
  const double th = 0.7;
  n = surface_normal(s, {2 * std::cos(th), std::sin(th), 10});
  const Vec3 expect = normalize(Vec3{std::cos(th) / 2, std::sin(th), 0});
  EXPECT_NEAR(n.x, expect.x, 1e-12);
  EXPECT_NEAR(n.y, expect.y, 1e-12);
  EXPECT_NEAR(n.z, 0, 1e-12);
}

TEST(Sphere, RotatedEllipsoidNormalIsInverseTranspose) {
  // Scale <1,3,1> then rotate about z by 90° (+x -> +y, +y -> -x): long axis along world x.
  const Primitive s = transformed(sphere({0, 0, 0}, 1), Matrix::scaling({1, 3, 1}) * Matrix::rotation_axis(2, 90));
  const Intersections xs = intersect_all(s, ray({-10, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 7, 1e-12);
  EXPECT_NEAR(xs.t[1], 13, 1e-12);
  // World ellipse x²/9 + y² = 1; normal ∝ (x/9, y).
  const double th = 1.1;
  const Vec3 p{3 * std::cos(th), std::sin(th), 0};
  const Vec3 n = surface_normal(s, p);
  const Vec3 expect = normalize(Vec3{p.x / 9, p.y, 0});
  EXPECT_NEAR(n.x, expect.x, 1e-12);
  EXPECT_NEAR(n.y, expect.y, 1e-12);
}

TEST(Sphere, TransformedDepthToleranceAppliesInObjectSpace) {
  // A unit sphere scaled by 100: POV-Ray compares DEPTH_TOLERANCE with the object-space depth, so a surface 5e-5
  // ahead in world units (5e-7 in object units) is dropped while 2e-4 (2e-6 object) is kept.
  const Primitive s = transformed(sphere({0, 0, 0}, 1), Matrix::scaling({100, 100, 100}));
  Intersections xs = intersect_all(s, ray({0, 0, -100 - 5e-5}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 200 + 5e-5, 1e-9);
  xs = intersect_all(s, ray({0, 0, -100 - 2e-4}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 2e-4, 1e-10);
  // And MAX_DISTANCE too: a sphere scaled by 1e-3 at 5e6 is 5e9 object units away: dropped.
  const Primitive tiny = transformed(sphere({0, 0, 0}, 1), Matrix::scaling({1e-3, 1e-3, 1e-3}) *
                                                              Matrix::translation({0, 0, 5e6}));
  EXPECT_EQ(intersect_all(tiny, ray({0, 0, 0}, {0, 0, 1})).count, 0);
}

TEST(Sphere, WorldBoundsContainTransformedSphere) {
  std::mt19937 rng(7);
  for (int k = 0; k < 200; ++k) {
    const Primitive s = transformed(sphere({0.5, -1, 2}, 1.5), random_mirroring_transform(rng, 0));
    const Bounds b = world_bounds(s);
    ASSERT_TRUE(b.finite());
    for (int j = 0; j < 50; ++j) {
      const Vec3 q = s.world_from_object.point(s.a + random_unit(rng) * s.radius);
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(q[i], b.lo[i] - 1e-9);
        EXPECT_LE(q[i], b.hi[i] + 1e-9);
      }
    }
  }
  const Bounds plain = world_bounds(sphere({1, 2, 3}, 2));
  EXPECT_EQ(plain.lo, (Vec3{-1, 0, 1}));
  EXPECT_EQ(plain.hi, (Vec3{3, 4, 5}));
  EXPECT_DOUBLE_EQ(plain.surface_area(), 96.0);
}

// Seeded random rays against random transformed spheres, checked against marching + bisection in world space.
TEST(Sphere, RandomRaysMatchWorldSpaceSolve) {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> pos(-20, 20), cen(-3, 3), rad(0.5, 3);
  int hits = 0, compared = 0;
  for (int k = 0; k < 3000; ++k) {
    Primitive s = sphere({cen(rng), cen(rng), cen(rng)}, rad(rng));
    if (k % 3 != 0) s = transformed(s, random_mirroring_transform(rng, 0));
    // Aim roughly at the shape so that most rays hit.
    const Vec3 origin{pos(rng), pos(rng), pos(rng)};
    const Vec3 target = (s.transformed ? s.world_from_object.point(s.a) : s.a) + random_unit(rng) * 3.0;
    const Ray r = ray(origin, target - origin);
    // Near-grazing rays (double root) are ill-conditioned for both solvers: skip them. f(t) is exactly quadratic.
    auto f = [&](double t) { return implicit(s, r.origin + r.direction * t); };
    const double c = f(0), b = 0.5 * (f(1) - f(-1)), a = 0.5 * (f(1) + f(-1)) - c;
    const double disc = b * b - 4 * a * c;
    if (std::abs(disc) < 1e-6 * b * b + 1e-9) continue;
    if (std::abs(c) < 1e-3) continue;  // origin on the surface
    const std::vector<double> ref = march_roots(s, r, 120.0, 6000);
    const Intersections xs = intersect_all(s, r);
    ++compared;
    ASSERT_EQ(static_cast<int>(ref.size()), xs.count) << "ray " << k;
    for (int i = 0; i < xs.count; ++i) {
      EXPECT_NEAR(xs.t[i], ref[i], 1e-9 * (1 + ref[i])) << "ray " << k;
      // The normal is the normalised world gradient of the implicit function (finite differences).
      const Vec3 p = r.origin + r.direction * xs.t[i];
      const double h = 1e-6;
      const Vec3 grad{(implicit(s, p + Vec3{h, 0, 0}) - implicit(s, p - Vec3{h, 0, 0})) / (2 * h),
                      (implicit(s, p + Vec3{0, h, 0}) - implicit(s, p - Vec3{0, h, 0})) / (2 * h),
                      (implicit(s, p + Vec3{0, 0, h}) - implicit(s, p - Vec3{0, 0, h})) / (2 * h)};
      const Vec3 n = surface_normal(s, p);
      const Vec3 g = normalize(grad);
      EXPECT_NEAR(length(n), 1.0, 1e-12);
      EXPECT_NEAR(n.x, g.x, 1e-6);
      EXPECT_NEAR(n.y, g.y, 1e-6);
      EXPECT_NEAR(n.z, g.z, 1e-6);
    }
    hits += xs.count > 0;
  }
  EXPECT_GT(compared, 2500);
  EXPECT_GT(hits, 1000);
}

// A ray leaving the surface outward from a hit point must not find the same surface again beyond MIN_ISECT_DEPTH,
// and an inward ray must find only the far side.
TEST(Sphere, ReintersectionFromHitPoint) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> pos(-20, 20);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    Primitive s = sphere({1, -2, 0.5}, 2.5);
    if (k % 2) s = transformed(s, random_mirroring_transform(rng, 0));
    const Vec3 origin{pos(rng), pos(rng), pos(rng)};
    const Vec3 target = s.transformed ? s.world_from_object.point(s.a) : s.a;
    if (inside(s, origin)) continue;  // from inside, the reflection legitimately meets the sphere again
    const Ray r = ray(origin, target + random_unit(rng) - origin);
    const Accelerator single(std::vector<Primitive>{s});
    const Hit h = single.closest_hit(r, tolerance::min_isect_depth, tolerance::bound_huge);
    if (!h.found()) continue;
    const Vec3 p = r.origin + r.direction * h.t;
    Vec3 n = surface_normal(s, p);
    if (dot(n, r.direction) > 0) n = -n;  // toward the viewer
    // Mirror reflection points away from the convex surface: no hit at all.
    const Vec3 reflected = r.direction - n * (2 * dot(r.direction, n));
    EXPECT_FALSE(single.closest_hit({p, normalize(reflected)}, tolerance::min_isect_depth, tolerance::bound_huge)
                     .found())
        << "ray " << k;
    // Continuing straight through: the next hit is the far side, well beyond the tolerance.
    const Hit through = single.closest_hit({p, r.direction}, tolerance::min_isect_depth, tolerance::bound_huge);
    if (through.found()) {
      const Intersections xs = intersect_all(s, r);
      ASSERT_EQ(xs.count, 2);
      EXPECT_NEAR(through.t, xs.t[1] - xs.t[0], 1e-8 * (1 + xs.t[1]));
    }
    ++checked;
  }
  EXPECT_GT(checked, 1000);
}

}  // namespace

// Plane intersection, normal, inside and bounds: hand-computed cases, POV-Ray's tolerance edges, and seeded random
// transformed planes checked against the plane equation solved directly in world space.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "geometry_kit.hpp"
#include "renderer/geometry.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

TEST(Plane, StraightDown) {
  const Primitive p = plane({0, 1, 0}, 0);
  const Intersections xs = intersect_all(p, ray({0, 5, 0}, {0, -1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_DOUBLE_EQ(xs.t[0], 5.0);
  EXPECT_EQ(surface_normal(p, {0, 0, 0}), (Vec3{0, 1, 0}));
}

TEST(Plane, OffsetAndOblique) {
  // Surface y = 2 (distance along the unit normal); ray from the origin along (1,1,0)/√2 meets it at t = 2√2.
  const Primitive p = plane({0, 1, 0}, 2);
  Intersections xs = intersect_all(p, ray({0, 0, 0}, {1, 1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 2 * std::sqrt(2.0), 1e-14);
  // Hits from either side: the plane is one surface, not a half-space boundary for intersections.
  xs = intersect_all(p, ray({0, 7, 0}, {0, -1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_DOUBLE_EQ(xs.t[0], 5.0);
  // Normal <1,1,0> with distance √2: surface x + y = 2.
  const Primitive q = plane({1, 1, 0}, std::sqrt(2.0));
  xs = intersect_all(q, ray({0, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 2.0, 1e-14);
}

TEST(Plane, BehindAndParallelMiss) {
  const Primitive p = plane({0, 1, 0}, 0);
  EXPECT_EQ(intersect_all(p, ray({0, 5, 0}, {0, 1, 0})).count, 0);
  EXPECT_EQ(intersect_all(p, ray({0, 5, 0}, {1, 0, 0})).count, 0);
  // |N·D| = 5e-11 < EPSILON: parallel, misses even though the root (2e6) would be in range.
  EXPECT_EQ(intersect_all(p, Ray{{0, 1e-4, 0}, {std::sqrt(1 - 25e-22), -5e-11, 0}}).count, 0);
  // |N·D| = 2e-10: a hit at 5e5.
  const Intersections xs = intersect_all(p, Ray{{0, 1e-4, 0}, {std::sqrt(1 - 4e-20), -2e-10, 0}});
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 5e5, 1e-6);
}

TEST(Plane, MaxDistanceEdge) {
  // pipeline docs §8 [V item8_tolerances]: a plane 9.9e6 away is visible, 1.01e7 away is not.
  EXPECT_EQ(intersect_all(plane({0, 0, -1}, -9.9e6), ray({0, 0, 0}, {0, 0, 1})).count, 1);
  EXPECT_EQ(intersect_all(plane({0, 0, -1}, -1.01e7), ray({0, 0, 0}, {0, 0, 1})).count, 0);
  // planes.cpp compares with <= MAX_DISTANCE: exactly 1e7 still hits.
  EXPECT_EQ(intersect_all(plane({0, 0, 1}, 1e7), ray({0, 0, 0}, {0, 0, 1})).count, 1);
}

TEST(Plane, DepthTolerance) {
  const Primitive p = plane({0, 1, 0}, 0);
  EXPECT_EQ(intersect_all(p, ray({0, 0, 0}, {0, -1, 0})).count, 0);       // on the surface
  EXPECT_EQ(intersect_all(p, ray({0, 5e-7, 0}, {0, -1, 0})).count, 0);    // closer than 1e-6
  EXPECT_EQ(intersect_all(p, ray({0, 2e-6, 0}, {0, -1, 0})).count, 1);    // farther than 1e-6
}

TEST(Plane, InsideIncludesSurfaceAndEpsilonSkin) {
  Primitive p = plane({0, 1, 0}, 1);
  EXPECT_TRUE(inside(p, {0, -5, 0}));
  EXPECT_TRUE(inside(p, {3, 1, 4}));            // on the surface
  EXPECT_TRUE(inside(p, {0, 1 + 5e-11, 0}));    // within the 1e-10 skin
  EXPECT_FALSE(inside(p, {0, 1 + 2e-10, 0}));
  EXPECT_FALSE(inside(p, {0, 3, 0}));
  // inverse = plane with N and d negated: the surface and the skin on the other side are inside.
  p.inverse = true;
  EXPECT_TRUE(inside(p, {0, 3, 0}));
  EXPECT_TRUE(inside(p, {3, 1, 4}));
  EXPECT_TRUE(inside(p, {0, 1 - 5e-11, 0}));
  EXPECT_FALSE(inside(p, {0, 1 - 2e-10, 0}));
  EXPECT_FALSE(inside(p, {0, -5, 0}));
}

TEST(Plane, BoundsAreInfinite) {
  const Bounds b = world_bounds(plane({0, 1, 0}, 0));
  EXPECT_FALSE(b.finite());
  const Bounds t = world_bounds(transformed(plane({0, 1, 0}, 0), Matrix::translation({1, 2, 3})));
  EXPECT_FALSE(t.finite());
}

TEST(Plane, RotatedAndTranslated) {
  // y = 0 rotated about z by 90° (+y -> -x) and moved to x = 3: the surface x = 3 with normal -x.
  const Primitive p =
      transformed(plane({0, 1, 0}, 0), Matrix::rotation_axis(2, 90) * Matrix::translation({3, 0, 0}));
  const Intersections xs = intersect_all(p, ray({0, 0, 0}, {1, 0, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 3, 1e-14);
  const Vec3 n = surface_normal(p, {3, 0, 0});
  EXPECT_NEAR(n.x, -1, 1e-15);
  EXPECT_NEAR(n.y, 0, 1e-15);
  EXPECT_TRUE(inside(p, {4, 0, 0}));
  EXPECT_FALSE(inside(p, {2, 0, 0}));
}

TEST(Plane, NonUniformScaleNormalAndDepth) {
  // x + y = 0 scaled <2,1,1>: world surface x/2 + y = 0, normal ∝ (1/2, 1, 0).
  const Primitive p = transformed(plane({1, 1, 0}, 0), Matrix::scaling({2, 1, 1}));
  const Vec3 n = surface_normal(p, {0, 0, 0});
  const Vec3 expect = normalize(Vec3{0.5, 1, 0});
  EXPECT_NEAR(n.x, expect.x, 1e-15);
  EXPECT_NEAR(n.y, expect.y, 1e-15);
  // From (4, 0, 0) straight down -y: meets x/2 + y = 0 at y = -2, world depth 2.
  const Intersections xs = intersect_all(p, ray({4, 0, 0}, {0, -1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 2, 1e-14);
}

TEST(Plane, TransformedDepthToleranceIsWorld) {
  // planes.cpp does not normalise the object-space direction, so the tolerance is on the world depth even under a
  // large scale: 5e-7 world units from the surface misses, 2e-6 hits.
  const Primitive p = transformed(plane({0, 1, 0}, 1), Matrix::scaling({100, 100, 100}));
  EXPECT_EQ(intersect_all(p, ray({0, 100 + 5e-7, 0}, {0, -1, 0})).count, 0);
  const Intersections xs = intersect_all(p, ray({0, 100 + 2e-6, 0}, {0, -1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], 2e-6, 1e-12);
}

// Random transformed planes against the plane equation in world space: a point on the plane and the world normal
// computed from three transformed surface points (independent of the inverse-transpose path).
TEST(Plane, RandomRaysMatchWorldSpacePlane) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> pos(-20, 20), dist(-4, 4);
  int hits = 0;
  for (int k = 0; k < 5000; ++k) {
    Primitive p = plane(random_unit(rng), dist(rng));
    if (k % 4 != 0) p = transformed(p, random_transform(rng));
    // Three object-space points on the plane, carried to world space.
    const Vec3 n0 = p.a;
    const Vec3 u = normalize(cross(n0, std::abs(n0.x) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 1, 0}));
    const Vec3 v = cross(n0, u);
    const Vec3 o0 = n0 * p.radius;
    auto world = [&](Vec3 q) { return p.transformed ? p.world_from_object.point(q) : q; };
    const Vec3 w0 = world(o0), w1 = world(o0 + u), w2 = world(o0 + v);
    Vec3 wn = normalize(cross(w1 - w0, w2 - w0));
    // Orient like the object normal: a point on the +N side maps to the +wn side.
    if (dot(world(o0 + n0) - w0, wn) < 0) wn = -wn;

    const Ray r = ray({pos(rng), pos(rng), pos(rng)}, random_unit(rng));
    const double denom = dot(wn, r.direction);
    const double t_ref = dot(wn, w0 - r.origin) / denom;
    const Intersections xs = intersect_all(p, r);
    if (std::abs(denom) < 1e-3) continue;  // too close to parallel for a clean comparison
    if (t_ref > 1e-3) {
      ASSERT_EQ(xs.count, 1) << "ray " << k;
      EXPECT_NEAR(xs.t[0], t_ref, 1e-9 * (1 + t_ref)) << "ray " << k;
      const Vec3 n = surface_normal(p, r.origin + r.direction * xs.t[0]);
      EXPECT_NEAR(n.x, wn.x, 1e-9);
      EXPECT_NEAR(n.y, wn.y, 1e-9);
      EXPECT_NEAR(n.z, wn.z, 1e-9);
      ++hits;
    } else if (t_ref < -1e-3) {
      EXPECT_EQ(xs.count, 0) << "ray " << k;
    }
    // Inside agrees with the world side of the plane for the ray origin (well away from the surface).
    const double side = dot(wn, r.origin - w0);
    if (std::abs(side) > 1e-6) {
      EXPECT_EQ(inside(p, r.origin), side < 0) << "ray " << k;
    }
  }
  EXPECT_GT(hits, 1500);
}

TEST(Plane, ReintersectionFromHitPoint) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> pos(-20, 20);
  int checked = 0;
  for (int k = 0; k < 2000; ++k) {
    Primitive p = plane(random_unit(rng), 1.5);
    if (k % 2) p = transformed(p, random_transform(rng));
    const Accelerator single(std::vector<Primitive>{p});
    const Ray r = ray({pos(rng), pos(rng), pos(rng)}, random_unit(rng));
    const Hit h = single.closest_hit(r, tolerance::min_isect_depth, tolerance::bound_huge);
    if (!h.found()) continue;
    const Vec3 at = r.origin + r.direction * h.t;
    Vec3 n = surface_normal(p, at);
    if (dot(n, r.direction) > 0) n = -n;
    const Vec3 reflected = normalize(r.direction - n * (2 * dot(r.direction, n)));
    EXPECT_FALSE(single.closest_hit({at, reflected}, tolerance::min_isect_depth, tolerance::bound_huge).found());
    EXPECT_FALSE(single.closest_hit({at, r.direction}, tolerance::min_isect_depth, tolerance::bound_huge).found());
    ++checked;
  }
  EXPECT_GT(checked, 800);
}

}  // namespace

// Cylinder: hand-computed hits, POV-Ray's cap/open/inside rules, and seeded random rays against random transformed
// cylinders checked against marching on the written solid (end points, radius) in world space.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quadric_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

Primitive cylinder(Vec3 p1, Vec3 p2, double r, bool open = false, const Matrix& m = Matrix::identity()) {
  return make_cylinder(Cylinder{p1, p2, r, open}, m);
}

// Membership of the written solid: the point projected on the axis lies between the ends and within the radius.
bool in_written_cylinder(Vec3 p1, Vec3 p2, double r, Vec3 q) {
  const Vec3 axis = p1 - p2;
  const double h = dot(q - p2, axis) / dot(axis, axis);
  const Vec3 radial = q - (p2 + axis * h);
  return h > 0 && h < 1 && dot(radial, radial) < r * r;
}

TEST(Cylinder, AxisAlignedHitsSideAndCaps) {
  const Primitive c = cylinder({0, 0, 0}, {0, 2, 0}, 1);
  Intersections xs = intersect_all(c, ray({-5, 1, 0}, {1, 0, 0}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 4, 1e-12);
  EXPECT_NEAR(xs.t[1], 6, 1e-12);
  Vec3 n = surface_normal(c, {-1, 1, 0});
  EXPECT_NEAR(n.x, -1, 1e-12);
  EXPECT_NEAR(n.y, 0, 1e-12);
  xs = intersect_all(c, ray({0.5, 5, 0}, {0, -1, 0}));   // through both caps
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 3, 1e-12);
  EXPECT_NEAR(xs.t[1], 5, 1e-12);
  n = surface_normal(c, {0.5, 2, 0});
  EXPECT_NEAR(n.y, 1, 1e-12);
  n = surface_normal(c, {0.5, 0, 0});
  EXPECT_NEAR(n.y, -1, 1e-12);
}

TEST(Cylinder, OpenHasNoCapsButTheSameSolid) {
  const Primitive c = cylinder({0, 0, 0}, {0, 2, 0}, 1, true);
  EXPECT_EQ(intersect_all(c, ray({0.5, 5, 0}, {0, -1, 0})).count, 0);
  // Into the tube through the open end: only the inner wall.
  const Intersections xs = intersect_all(c, ray({0, 2.5, 0}, {1, -1, 0}));
  ASSERT_EQ(xs.count, 1);
  EXPECT_NEAR(xs.t[0], std::sqrt(2.0), 1e-12);
  EXPECT_TRUE(inside(c, {0, 1, 0}));
  // Open: the boundary counts as inside (+EPSILON); capped: it is outside (−EPSILON).
  EXPECT_TRUE(inside(c, {1, 1, 0}));
  EXPECT_TRUE(inside(c, {0, 2, 0}));
  EXPECT_FALSE(inside(cylinder({0, 0, 0}, {0, 2, 0}, 1), {1, 1, 0}));
  EXPECT_FALSE(inside(cylinder({0, 0, 0}, {0, 2, 0}, 1), {0, 2, 0}));
}

TEST(Cylinder, InverseNegatesInside) {
  Primitive c = cylinder({0, 0, 0}, {0, 0, 3}, 0.5);
  EXPECT_TRUE(inside(c, {0, 0, 1}));
  c.inverse = true;
  EXPECT_FALSE(inside(c, {0, 0, 1}));
  EXPECT_TRUE(inside(c, {0, 2, 1}));
}

TEST(Cylinder, NegativeRadiusIsTheSameCylinder) {
  const Primitive c = cylinder({0, 0, 0}, {3, 0, 0}, -0.5);
  const Intersections xs = intersect_all(c, ray({1, 5, 0}, {0, -1, 0}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 4.5, 1e-12);
  EXPECT_NEAR(xs.t[1], 5.5, 1e-12);
  EXPECT_NEAR(surface_normal(c, {1, 0.5, 0}).y, 1, 1e-12);
}

TEST(Cylinder, DepthToleranceIsOneNanometreInCanonicalSpace) {
  const Primitive c = cylinder({0, 0, 0}, {0, 1, 0}, 1);
  EXPECT_EQ(intersect_all(c, ray({-1 - 5e-10, 0.5, 0}, {1, 0, 0})).count, 1);   // the near root is dropped
  EXPECT_EQ(intersect_all(c, ray({-1 - 5e-9, 0.5, 0}, {1, 0, 0})).count, 2);
}

TEST(Cylinder, BoundsContainTheSurface) {
  std::mt19937 rng(3);
  for (int k = 0; k < 100; ++k) {
    const Matrix m = random_mirroring_transform(rng, 1);
    const Primitive c = cylinder({0.3, -1, 0.2}, {1, 2, -0.5}, 0.7, false, m);
    const Bounds b = world_bounds(c);
    for (int j = 0; j < 50; ++j) {
      const Vec3 u = random_unit(rng);
      const Vec3 q = c.world_from_object.point(Vec3{u.x / std::hypot(u.x, u.y), u.y / std::hypot(u.x, u.y),
                                                    (u.z + 1) / 2});
      for (int i = 0; i < 3; ++i) {
        EXPECT_GE(q[i], b.lo[i] - 1e-9);
        EXPECT_LE(q[i], b.hi[i] + 1e-9);
      }
    }
  }
}

TEST(Cylinder, RandomRaysMatchMarchingOnTheWrittenSolid) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> pos(-15, 15), end(-2, 2), rad(0.3, 2);
  int compared = 0, hits = 0;
  for (int k = 0; k < 1500; ++k) {
    const Vec3 p1{end(rng), end(rng), end(rng)}, p2{end(rng), end(rng), end(rng)};
    const double r = rad(rng);
    const Matrix m = k % 2 ? random_mirroring_transform(rng, 2) : Matrix::identity();
    const Matrix inv = m.inverse();
    const Primitive c = cylinder(p1, p2, r, false, m);
    auto member = [&](Vec3 w) { return in_written_cylinder(p1, p2, r, inv.point(w)); };
    const Vec3 origin{pos(rng), pos(rng), pos(rng)};
    const Vec3 target = m.point((p1 + p2) * 0.5) + random_unit(rng) * 2.0;
    const Ray rr = ray(origin, target - origin);
    const std::vector<double> ref = crossings(member, rr, 0.0, 80.0, 4000);
    const Intersections xs = intersect_all(c, rr);
    // A ray through a rim reports the side and the cap at the same point: count distinct depths.
    std::vector<double> got;
    for (int i = 0; i < xs.count; ++i)
      if (got.empty() || xs.t[i] - got.back() > 1e-7) got.push_back(xs.t[i]);
    if (got.size() != ref.size()) {
      // Allowed only when the ray passes within rounding of a rim or grazes the side.
      continue;
    }
    ++compared;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_NEAR(got[i], ref[i], 1e-8 * (1 + ref[i])) << "ray " << k;
      const Vec3 p = rr.origin + rr.direction * got[i];
      const Vec3 q = inv.point(p);
      const Vec3 axis = p1 - p2;
      const double h = dot(q - p2, axis) / dot(axis, axis);
      const Vec3 radial = q - (p2 + axis * h);
      Vec3 expect = radial;   // side unless within 1e-6 of an end plane
      if (std::abs(h - 1) * length(axis) < 1e-6) expect = axis;
      else if (std::abs(h) * length(axis) < 1e-6) expect = -axis;
      const Vec3 want = world_normal(m, expect), n = surface_normal(c, p);
      EXPECT_NEAR(dot(n, want), 1.0, 1e-8) << "ray " << k;
    }
    hits += !got.empty();
  }
  EXPECT_GT(compared, 1450);
  EXPECT_GT(hits, 600);
}

TEST(Cylinder, ReflectedRayDoesNotFindTheSameSurface) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> pos(-10, 10);
  int checked = 0;
  for (int k = 0; k < 1000; ++k) {
    const Matrix m = random_transform(rng);
    const Primitive c = cylinder({0, -1, 0}, {0, 1, 0}, 1, false, m);
    const Vec3 origin{pos(rng), pos(rng), pos(rng)};
    if (inside(c, origin)) continue;
    const Ray r = ray(origin, m.point({0, 0, 0}) + random_unit(rng) - origin);
    const Accelerator single(std::vector<Primitive>{c});
    const Hit h = single.closest_hit(r, tolerance::min_isect_depth, tolerance::bound_huge);
    if (!h.found()) continue;
    const Vec3 p = r.origin + r.direction * h.t;
    Vec3 n = surface_normal(c, p);
    if (dot(n, r.direction) > 0) n = -n;
    const Vec3 reflected = r.direction - n * (2 * dot(r.direction, n));
    EXPECT_FALSE(single.closest_hit({p, normalize(reflected)}, tolerance::min_isect_depth, tolerance::bound_huge)
                     .found()) << "ray " << k;   // a convex solid: the reflection leaves it
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

}  // namespace

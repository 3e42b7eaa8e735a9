// Cone: hand-computed hits, a radius-0 tip, open cones, equal radii (a cylinder), POV-Ray's inside rule, and seeded
// random rays against random transformed cones checked against marching on the written solid.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "quadric_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

Primitive cone(Vec3 p1, double r1, Vec3 p2, double r2, bool open = false, const Matrix& m = Matrix::identity()) {
  return make_cone(Cone{p1, r1, p2, r2, open}, m);
}

// The written solid: between the end planes, within the linearly interpolated radius.
bool in_written_cone(Vec3 p1, double r1, Vec3 p2, double r2, Vec3 q) {
  const Vec3 axis = p2 - p1;
  const double h = dot(q - p1, axis) / dot(axis, axis);
  const Vec3 radial = q - (p1 + axis * h);
  const double r = r1 + (r2 - r1) * h;
  return h > 0 && h < 1 && dot(radial, radial) < r * r;
}

TEST(Cone, TipConeHitsSideAndBase) {
  // Base radius 1 at y = 0, tip at y = 2.
  const Primitive c = cone({0, 0, 0}, 1, {0, 2, 0}, 0);
  EXPECT_EQ(c.type, ShapeType::cone);
  Intersections xs = intersect_all(c, ray({-5, 1, 0}, {1, 0, 0}));   // radius 0.5 at y = 1
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 4.5, 1e-12);
  EXPECT_NEAR(xs.t[1], 5.5, 1e-12);
  // Side normal of x = 1 − y/2: ∝ (1, 1/2, 0).
  const Vec3 n = surface_normal(c, {-0.5, 1, 0});
  EXPECT_NEAR(n.x, -2 / std::sqrt(5.0), 1e-12);
  EXPECT_NEAR(n.y, 1 / std::sqrt(5.0), 1e-12);
  xs = intersect_all(c, ray({0.2, -3, 0}, {0, 1, 0}));   // base, then the side at y = 1.6
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 3, 1e-12);
  EXPECT_NEAR(xs.t[1], 4.6, 1e-12);
  EXPECT_NEAR(surface_normal(c, {0.2, 0, 0}).y, -1, 1e-12);
}

TEST(Cone, BiggerEndSecondIsTheSameCone) {
  const Primitive a = cone({0, 0, 0}, 0.5, {0, 2, 0}, 1.5), b = cone({0, 2, 0}, 1.5, {0, 0, 0}, 0.5);
  for (double y : {0.3, 1.0, 1.7}) {
    const Intersections xa = intersect_all(a, ray({-5, y, 0.1}, {1, 0, 0}));
    const Intersections xb = intersect_all(b, ray({-5, y, 0.1}, {1, 0, 0}));
    ASSERT_EQ(xa.count, 2);
    ASSERT_EQ(xb.count, 2);
    EXPECT_NEAR(xa.t[0], xb.t[0], 1e-12);
    EXPECT_NEAR(xa.t[0], 5 - std::sqrt(std::pow(0.5 + y / 2, 2) - 0.01), 1e-12);
  }
}

TEST(Cone, EqualRadiiMakeACylinder) {
  EXPECT_EQ(cone({0, 0, 0}, 0.5, {0, 1, 0}, 0.5).type, ShapeType::cylinder);
  EXPECT_EQ(cone({0, 0, 0}, 0.5, {0, 1, 0}, 0.5 + 5e-11).type, ShapeType::cylinder);
  // POV-Ray's second rule: (r_big − r_small)² / r_big < EPSILON is a cylinder too (here 2e-12).
  EXPECT_EQ(cone({0, 0, 0}, 0.5, {0, 1, 0}, 0.5 + 1e-6).type, ShapeType::cylinder);
  EXPECT_EQ(cone({0, 0, 0}, 0.5, {0, 1, 0}, 0.5 + 1e-4).type, ShapeType::cone);
}

TEST(Cone, OpenConeHasNoCapsAndAWiderInside) {
  const Primitive c = cone({0, 0, 0}, 1, {0, 2, 0}, 0.5, true);
  EXPECT_EQ(intersect_all(c, ray({0, 5, 0}, {0, -1, 0})).count, 0);
  EXPECT_TRUE(inside(c, {0, 1, 0}));
  EXPECT_TRUE(inside(c, {0, 0, 0}));    // on the missing base: +EPSILON keeps it in
  EXPECT_FALSE(inside(cone({0, 0, 0}, 1, {0, 2, 0}, 0.5), {0, 0, 0}));
  EXPECT_FALSE(inside(c, {0.9, 1, 0}));
}

TEST(Cone, NegativeRadiusGivesPovRaysDoubleCone) {
  // r1 = 1 at y = 0, r2 = −1 at y = 2: POV-Ray's arithmetic extends the cone through its tip at y = 1.
  const Primitive c = cone({0, 0, 0}, 1, {0, 2, 0}, -1);
  const Intersections xs = intersect_all(c, ray({-5, 1.5, 0}, {1, 0, 0}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 4.5, 1e-12);
}

TEST(Cone, RandomRaysMatchMarchingOnTheWrittenSolid) {
  std::mt19937 rng(4048);
  std::uniform_real_distribution<double> pos(-15, 15), end(-2, 2), rad(0.0, 2), u(0, 1);
  int compared = 0, hits = 0;
  for (int k = 0; k < 1500; ++k) {
    const Vec3 p1{end(rng), end(rng), end(rng)}, p2{end(rng), end(rng), end(rng)};
    const double r1 = rad(rng), r2 = u(rng) < 0.3 ? 0.0 : rad(rng);
    const Matrix m = k % 2 ? random_mirroring_transform(rng, 0) : Matrix::identity();
    const Matrix inv = m.inverse();
    const Primitive c = cone(p1, r1, p2, r2, false, m);
    auto member = [&](Vec3 w) { return in_written_cone(p1, r1, p2, r2, inv.point(w)); };
    const Vec3 origin{pos(rng), pos(rng), pos(rng)};
    const Ray rr = ray(origin, m.point((p1 + p2) * 0.5) + random_unit(rng) * 1.5 - origin);
    const std::vector<double> ref = crossings(member, rr, 0.0, 80.0, 4000);
    const Intersections xs = intersect_all(c, rr);
    std::vector<double> got;
    for (int i = 0; i < xs.count; ++i)
      if (got.empty() || xs.t[i] - got.back() > 1e-7) got.push_back(xs.t[i]);
    if (got.size() != ref.size()) continue;   // through a rim or the tip within rounding
    ++compared;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_NEAR(got[i], ref[i], 1e-8 * (1 + ref[i])) << "ray " << k;
      const Vec3 p = rr.origin + rr.direction * got[i];
      // The outward normal is the gradient of the membership's defining function: finite differences on
      // radial² − r(h)² and the end planes.
      const Vec3 q = inv.point(p);
      const Vec3 axis = p2 - p1;
      const double h = dot(q - p1, axis) / dot(axis, axis);
      Vec3 expect;
      if (std::abs(h) * length(axis) < 1e-6) expect = -axis;
      else if (std::abs(h - 1) * length(axis) < 1e-6) expect = axis;
      else {
        auto f = [&](Vec3 x) {
          const double hh = dot(x - p1, axis) / dot(axis, axis);
          const Vec3 radial = x - (p1 + axis * hh);
          const double r = r1 + (r2 - r1) * hh;
          return std::sqrt(dot(radial, radial)) - std::abs(r);
        };
        const double e = 1e-6;
        expect = Vec3{f(q + Vec3{e, 0, 0}) - f(q - Vec3{e, 0, 0}), f(q + Vec3{0, e, 0}) - f(q - Vec3{0, e, 0}),
                      f(q + Vec3{0, 0, e}) - f(q - Vec3{0, 0, e})};
      }
      const Vec3 want = world_normal(m, expect), n = surface_normal(c, p);
      EXPECT_NEAR(dot(n, want), 1.0, 1e-6) << "ray " << k;
    }
    hits += !got.empty();
  }
  EXPECT_GT(compared, 1450);
  EXPECT_GT(hits, 500);
}

TEST(Cone, ReflectedRayDoesNotFindTheSameSurface) {
  std::mt19937 rng(78);
  std::uniform_real_distribution<double> pos(-10, 10);
  int checked = 0;
  for (int k = 0; k < 1000; ++k) {
    const Matrix m = random_transform(rng);
    const Primitive c = cone({0, -1, 0}, 1.2, {0, 1, 0}, 0.2, false, m);
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
                     .found()) << "ray " << k;
    ++checked;
  }
  EXPECT_GT(checked, 300);
}

}  // namespace

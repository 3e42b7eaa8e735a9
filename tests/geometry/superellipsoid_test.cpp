// Superellipsoid: hand-computed hits, POV-Ray's inside rule and bounds, seeded random rays against marching on the
// implicit form written with std::pow, normals against its numeric gradient, and rays leaving from a hit.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <random>

#include "quadric_kit.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

Primitive superellipsoid(double e, double n, const Matrix& m = Matrix::identity()) {
  return make_superellipsoid(Superellipsoid{e, n}, m);
}

// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) − 1 in object space: negative inside.
double implicit(double e, double n, Vec3 q) {
  return std::pow(std::pow(std::abs(q.x), 2 / e) + std::pow(std::abs(q.y), 2 / e), e / n) +
         std::pow(std::abs(q.z), 2 / n) - 1;
}

std::vector<double> all_roots(const Primitive& p, const Ray& r) {
  HitBuffer hits;
  collect_hits(p, r, hits);
  std::vector<double> t;
  for (const auto& h : hits) t.push_back(h.t);
  std::sort(t.begin(), t.end());
  return t;
}

TEST(Superellipsoid, ExponentOneIsTheUnitSphere) {
  const Primitive s = superellipsoid(1, 1);
  const Intersections xs = intersect_all(s, ray({0.6, 0, -5}, {0, 0, 1}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 4.2, 1e-9);
  EXPECT_NEAR(xs.t[1], 5.8, 1e-9);
  const Vec3 n = surface_normal(s, {0.6, 0, -0.8});
  EXPECT_NEAR(n.x, 0.6, 1e-9);
  EXPECT_NEAR(n.z, -0.8, 1e-9);
}

TEST(Superellipsoid, SmallExponentsApproachTheCube) {
  // With e = n = 0.1 the faces are flat to within 2^-5 of the cube's: a ray along x meets x = ±1 almost exactly.
  const Primitive s = superellipsoid(0.1, 0.1);
  const Intersections xs = intersect_all(s, ray({-5, 0.3, 0.2}, {1, 0, 0}));
  ASSERT_EQ(xs.count, 2);
  EXPECT_NEAR(xs.t[0], 4, 1e-3);
  EXPECT_NEAR(xs.t[1], 6, 1e-3);
  EXPECT_NEAR(surface_normal(s, {1, 0.3, 0.2}).x, 1, 1e-6);
}

TEST(Superellipsoid, PinchedStarAlongAChordNearItsArms) {
  // e = n = 3 (powers 2/3): the astroid-like star. Along x at y = 0.05, z = 0 the ray crosses the two arms' tips
  // region and the middle: |x|^(2/3) = 1 − 0.05^(2/3) on each side.
  const Primitive s = superellipsoid(3, 3);
  const double x = std::pow(1 - std::pow(0.05, 2.0 / 3.0), 1.5);
  const std::vector<double> t = all_roots(s, ray({-5, 0.05, 0}, {1, 0, 0}));
  ASSERT_EQ(t.size(), 2u);
  EXPECT_NEAR(t[0], 5 - x, 1e-7);
  EXPECT_NEAR(t[1], 5 + x, 1e-7);
}

TEST(Superellipsoid, InsideCountsTheSurfaceAndHonoursInverse) {
  Primitive s = superellipsoid(1, 1);
  EXPECT_TRUE(inside(s, {0, 0, 0}));
  EXPECT_TRUE(inside(s, {1, 0, 0}));   // on the surface: f = 0 < 1e-10
  EXPECT_FALSE(inside(s, {0.8, 0.8, 0}));
  s.inverse = true;
  EXPECT_FALSE(inside(s, {0, 0, 0}));
  EXPECT_TRUE(inside(s, {0.8, 0.8, 0}));
}

TEST(Superellipsoid, BoundsAreTheCubeCarriedToWorld) {
  const Bounds b = world_bounds(superellipsoid(0.5, 2, Matrix::scaling({2, 1, 1}) * Matrix::translation({1, 0, 0})));
  EXPECT_NEAR(b.lo.x, -1.0002, 1e-12);
  EXPECT_NEAR(b.hi.x, 3.0002, 1e-12);
  EXPECT_NEAR(b.hi.y, 1.0001, 1e-12);
}

TEST(Superellipsoid, RandomRaysMatchMarchingOnTheImplicitForm) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> pos(-6, 6), expo(0.2, 3.0), u(0, 1);
  int compared = 0, hits = 0;
  for (int k = 0; k < 1200; ++k) {
    const double e = expo(rng), n = expo(rng);
    const Matrix m = k % 2 ? random_mirroring_transform(rng, 2) : Matrix::identity();
    const Matrix inv = m.inverse();
    const Primitive s = superellipsoid(e, n, m);
    auto member = [&](Vec3 w) { return implicit(e, n, inv.point(w)) < 0; };
    const Vec3 origin = m.point(Vec3{pos(rng), pos(rng), pos(rng)});
    const Vec3 target = m.point(random_unit(rng) * (0.9 * u(rng)));
    const Ray r = ray(origin, target - origin);
    if (inside(s, origin)) continue;
    const std::vector<double> ref = crossings(member, r, 0.0, 200.0, 20000);
    const std::vector<double> got = all_roots(s, r);
    if (ref.size() != got.size()) continue;   // a ray grazing an edge or a pinched arm: counted either way
    ++compared;
    for (std::size_t i = 0; i < got.size(); ++i) {
      EXPECT_NEAR(got[i], ref[i], 1e-6 * (1 + ref[i])) << "ray " << k << " e " << e << " n " << n;
      const Vec3 q = inv.point(r.origin + r.direction * got[i]);
      const double h = 1e-6;
      const Vec3 grad{implicit(e, n, q + Vec3{h, 0, 0}) - implicit(e, n, q - Vec3{h, 0, 0}),
                      implicit(e, n, q + Vec3{0, h, 0}) - implicit(e, n, q - Vec3{0, h, 0}),
                      implicit(e, n, q + Vec3{0, 0, h}) - implicit(e, n, q - Vec3{0, 0, h})};
      if (length(grad) < 1e-5) continue;   // a crease or a tip: no defined gradient to compare with
      EXPECT_NEAR(dot(surface_normal(s, m.point(q)), world_normal(m, grad)), 1.0, 1e-4) << "ray " << k;
    }
    hits += !got.empty();
  }
  EXPECT_GT(compared, 1100);
  EXPECT_GT(hits, 900);
}

TEST(Superellipsoid, ARayLeavingAHitDoesNotFindTheSameSurface) {
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> expo(0.3, 2.5);
  for (int k = 0; k < 300; ++k) {
    const double e = expo(rng), n = expo(rng);
    const Primitive s = superellipsoid(e, n);
    const Vec3 origin = random_unit(rng) * 4;
    const Ray in = ray(origin, random_unit(rng) * 0.2 - origin);
    const std::optional<SurfaceHit> first = nearest_hit(s, in, tolerance::min_isect_depth, tolerance::bound_huge);
    if (!first) continue;
    const Ray next{in.origin + in.direction * first->t, in.direction};
    const std::optional<SurfaceHit> second = nearest_hit(s, next, tolerance::min_isect_depth, tolerance::bound_huge);
    if (second) {
      EXPECT_GT(second->t, 1e-4) << "ray " << k;
    }
    // Leaving outwards from the hit (back along the ray) finds nothing: the shape is star-shaped about its centre.
    const Ray back{next.origin, -in.direction};
    EXPECT_FALSE(nearest_hit(s, back, tolerance::min_isect_depth, tolerance::bound_huge)) << "ray " << k;
  }
}

}  // namespace

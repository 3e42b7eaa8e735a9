// Blob: seeded random rays against marching on the density written here from the components (a sphere's
// s·(1 − d²/R²)² with d the distance to its centre, a cylinder's with d the distance to its segment), normals
// against the density's numeric gradient, POV-Ray's inside rule, negative components, and rays leaving a hit.
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

double falloff(double strength, double d2, double r2) {
  if (d2 >= r2) return 0.0;
  const double k = 1.0 - d2 / r2;
  return strength * k * k;
}

double density(const Blob& b, Vec3 q) {
  double sum = 0;
  for (const auto& c : *b.components) {
    if (c.kind == BlobComponentKind::cylinder) {
      const Vec3 axis = c.apex - c.centre;
      const double s = std::clamp(dot(q - c.centre, axis) / dot(axis, axis), 0.0, 1.0);
      const Vec3 v = q - (c.centre + axis * s);
      sum += falloff(c.strength, dot(v, v), c.radius2);
    } else {
      const Vec3 v = c.transform.inverse().point(q) - c.centre;
      sum += falloff(c.strength, dot(v, v), c.radius2);
    }
  }
  return sum;
}

BlobComponent sphere_component(Vec3 centre, double radius, double strength) {
  BlobComponent c;
  c.centre = centre;
  c.radius2 = radius * radius;
  c.strength = strength;
  return c;
}

Blob random_blob(std::mt19937& rng) {
  std::uniform_real_distribution<double> pos(-1, 1), rad(0.5, 1.5), u(0, 1);
  auto list = std::make_shared<std::vector<BlobComponent>>();
  const int n = 1 + static_cast<int>(u(rng) * 4);
  for (int i = 0; i < n; ++i) {
    BlobComponent c = sphere_component({pos(rng), pos(rng), pos(rng)}, rad(rng), u(rng) < 0.2 ? -1.0 : 1.0 + u(rng));
    if (u(rng) < 0.3) {
      c.kind = BlobComponentKind::cylinder;
      c.apex = c.centre + random_unit(rng) * (0.5 + u(rng));
    } else if (u(rng) < 0.3) {
      c.kind = BlobComponentKind::ellipsoid;
      c.transform = Matrix::scaling({0.5 + u(rng), 0.5 + u(rng), 0.5 + u(rng)}) * Matrix::rotation({pos(rng) * 90, 0, 0});
    }
    list->push_back(c);
  }
  Blob b;
  b.threshold = 0.2 + 0.6 * u(rng);
  b.sturm = u(rng) < 0.3;
  b.components = std::move(list);
  return b;
}

TEST(Blob, OneSphereIsASphereOfTheThresholdRadius) {
  // s(1 − d²/R²)² = T at d = R·√(1 − √(T/s)).
  Blob b;
  b.threshold = 0.25;
  b.components = std::make_shared<std::vector<BlobComponent>>(1, sphere_component({0, 0, 0}, 2, 1));
  const Primitive p = make_blob(b, Matrix::identity());
  const double r = 2 * std::sqrt(1 - std::sqrt(0.25));
  HitBuffer hits;
  collect_hits(p, ray({-5, 0, 0}, {1, 0, 0}), hits);
  ASSERT_EQ(hits.size(), 2u);
  std::sort(hits.begin(), hits.end(), [](auto& a, auto& c) { return a.t < c.t; });
  EXPECT_NEAR(hits[0].t, 5 - r, 1e-9);
  EXPECT_NEAR(hits[1].t, 5 + r, 1e-9);
  EXPECT_NEAR(surface_normal(p, {-r, 0, 0}).x, -1, 1e-12);
  EXPECT_TRUE(inside(p, {0, 0, 0}));
  EXPECT_FALSE(inside(p, {r + 1e-3, 0, 0}));
}

TEST(Blob, ANegativeComponentCarvesAHole) {
  Blob b;
  b.threshold = 0.5;
  b.components = std::make_shared<std::vector<BlobComponent>>(
      std::vector<BlobComponent>{sphere_component({0, 0, 0}, 2, 2), sphere_component({0, 0, 0}, 0.8, -3)});
  const Primitive p = make_blob(b, Matrix::identity());
  EXPECT_FALSE(inside(p, {0, 0, 0}));
  EXPECT_TRUE(inside(p, {1, 0, 0}));
  const std::optional<SurfaceHit> h = nearest_hit(p, ray({0, 0, 0}, {0, 1, 0}), tolerance::min_isect_depth,
                                                  tolerance::bound_huge);
  ASSERT_TRUE(h);
  EXPECT_LT(h->t, 0.8);   // the wall of the hole comes first
  EXPECT_LT(surface_normal(*h, Vec3{0, h->t, 0}).y, 0);   // facing into the hole
}

TEST(Blob, RandomRaysMatchMarchingOnTheDensity) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> pos(-6, 6);
  int compared = 0, hits = 0;
  for (int k = 0; k < 800; ++k) {
    const Blob b = random_blob(rng);
    const Matrix m = k % 2 ? random_transform(rng) : Matrix::identity();
    const Matrix inv = m.inverse();
    const Primitive p = make_blob(b, m);
    auto member = [&](Vec3 w) { return density(b, inv.point(w)) > b.threshold; };
    const Vec3 origin = m.point(Vec3{pos(rng), pos(rng), pos(rng)});
    const Ray r = ray(origin, m.point(random_unit(rng) * 0.5) - origin);
    if (member(origin)) continue;
    const std::vector<double> ref = crossings(member, r, 0.0, 60.0, 30000);
    const std::optional<SurfaceHit> h = nearest_hit(p, r, tolerance::min_isect_depth, tolerance::bound_huge);
    const bool found = h.has_value();
    // A grazing ray (two crossings closer than the marching step) is counted either way.
    if (found != !ref.empty() || (ref.size() >= 2 && ref[1] - ref[0] < 1e-2)) continue;
    ++compared;
    if (!found) continue;
    ++hits;
    EXPECT_NEAR(h->t, ref[0], 1e-7 * (1 + ref[0])) << "ray " << k;
    const Vec3 q = inv.point(r.origin + r.direction * h->t);
    const double e = 1e-6;
    const Vec3 grad{density(b, q - Vec3{e, 0, 0}) - density(b, q + Vec3{e, 0, 0}),
                    density(b, q - Vec3{0, e, 0}) - density(b, q + Vec3{0, e, 0}),
                    density(b, q - Vec3{0, 0, e}) - density(b, q + Vec3{0, 0, e})};
    if (length(grad) < 1e-7) continue;
    EXPECT_NEAR(dot(surface_normal(p, m.point(q)), world_normal(m, grad)), 1.0, 1e-5) << "ray " << k;
  }
  EXPECT_GT(compared, 700);
  EXPECT_GT(hits, 250);
}

TEST(Blob, ARayLeavingAHitIgnoresTheNextCentimetre) {
  // POV-Ray's blob DEPTH_TOLERANCE is 1e-2: from a point on the surface nothing nearer is found.
  Blob b;
  b.threshold = 0.5;
  b.components = std::make_shared<std::vector<BlobComponent>>(1, sphere_component({0, 0, 0}, 2, 1));
  const Primitive p = make_blob(b, Matrix::identity());
  const double r = 2 * std::sqrt(1 - std::sqrt(0.5));
  const std::optional<SurfaceHit> h = nearest_hit(p, ray({-r, 0, 0}, {1, 0, 0}), tolerance::min_isect_depth,
                                                  tolerance::bound_huge);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 2 * r, 1e-9);
  EXPECT_FALSE(nearest_hit(p, ray({-r, 0, 0}, {-1, 0, 0}), tolerance::min_isect_depth, tolerance::bound_huge));
}

}  // namespace

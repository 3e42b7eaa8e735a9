// Triangle and polygon intersection: seeded random rays against an independent answer (plane intersection plus a
// barycentric inside test), POV-Ray's depth tolerance, and the watertight test on a fan of triangles.
#include <gtest/gtest.h>

#include "tests/geometry/mesh_kit.hpp"

namespace povtrace::test {
namespace {

// The independent answer: the ray meets the plane of (a, b, c) at t; inside when all barycentric weights are
// ≥ 0. Returns the margin (smallest weight) so that the caller can skip rays too close to an edge to decide.
bool reference_hit(const render::Ray& ray, Vec3 a, Vec3 b, Vec3 c, double& t, double& margin) {
  const Vec3 n = cross(b - a, c - a);
  const double nd = dot(n, ray.direction);
  if (std::fabs(nd) < 1e-12) return false;
  t = dot(n, a - ray.origin) / nd;
  const Vec3 q = ray.origin + ray.direction * t;
  const double n2 = dot(n, n);
  const double wb = dot(n, cross(q - a, c - a)) / n2, wc = dot(n, cross(b - a, q - a)) / n2;
  margin = std::min({wb, wc, 1.0 - wb - wc});
  return margin >= 0 && t > 1e-6;
}

TEST(Triangle, RandomRaysMatchAnIndependentAnswer) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> u(-2.0, 2.0);
  int hits = 0;
  for (int i = 0; i < 20000; ++i) {
    const Vec3 a{u(rng), u(rng), u(rng)}, b{u(rng), u(rng), u(rng)}, c{u(rng), u(rng), u(rng)};
    const render::Primitive p = triangle(a, b, c);
    // Aimed near the triangle (weights in [-0.3, 1.3]) so that many rays hit.
    std::uniform_real_distribution<double> w(-0.3, 1.3);
    const double wb = w(rng), wc = w(rng);
    const Vec3 aim = a + (b - a) * wb + (c - a) * wc;
    const Vec3 origin = Vec3{u(rng), u(rng), u(rng)} * 3.0;
    if (length(aim - origin) < 1e-3) continue;
    const render::Ray r = ray(origin, aim - origin);
    double t = 0, margin = 0;
    const bool expected = reference_hit(r, a, b, c, t, margin);
    if (std::fabs(margin) < 1e-9) continue;   // too close to an edge for the reference to decide
    const render::Intersections xs = render::intersect_all(p, r);
    ASSERT_EQ(xs.count, expected ? 1 : 0) << "ray " << i;
    if (expected) {
      EXPECT_NEAR(xs.t[0], t, 1e-9 * std::max(1.0, t));
      ++hits;
    }
  }
  EXPECT_GT(hits, 3000);   // about a fifth of the aimed rays land inside
}

TEST(Triangle, TransformMovesTheVerticesAndDepthToleranceIsWorld) {
  const render::Primitive p = triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, Matrix::scaling({100, 100, 100}));
  EXPECT_EQ(render::intersect_all(p, ray({50, 20, -3}, {0, 0, 1})).t[0], 3.0);
  // A root at depth 5e-7 is below DEPTH_TOLERANCE (1e-6) in world units even though the triangle is scaled.
  EXPECT_EQ(render::intersect_all(p, ray({50, 20, -5e-7}, {0, 0, 1})).count, 0);
  EXPECT_EQ(render::intersect_all(p, ray({50, 20, -2e-6}, {0, 0, 1})).count, 1);
  EXPECT_FALSE(render::inside(p, {0.1, 0.1, 0}));
}

TEST(Triangle, RaysThroughTheCentreOfAFanAlwaysHit) {
  // Eleven triangles around the origin in z = 0 (an irregular fan). Rays along the fan's spokes and exactly
  // through its centre, from many directions, must hit at least one triangle: none slips between them.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Vec3> rim;
  for (int k = 0; k < 11; ++k) {
    const double angle = 2 * M_PI * (k + jitter(rng)) / 11;
    rim.push_back({std::cos(angle) * 1.3, std::sin(angle) * 0.7, 0});
  }
  std::vector<render::Primitive> fan;
  for (int k = 0; k < 11; ++k) fan.push_back(triangle({0, 0, 0}, rim[k], rim[(k + 1) % 11]));
  for (int i = 0; i < 2000; ++i) {
    Vec3 d = random_unit(rng);
    if (std::fabs(d.z) < 0.05) continue;
    const Vec3 target = i % 2 == 0 ? Vec3{0, 0, 0} : rim[i % 11] * (0.5 * (1 + jitter(rng)));   // centre or spoke
    const render::Ray r{target - d * 4.0, d};
    int count = 0;
    for (const auto& p : fan) count += render::intersect_all(p, r).count;
    EXPECT_GE(count, 1) << "ray " << i << " leaked through the fan";
  }
}

TEST(Polygon, EvenOddFillWithAHole) {
  Polygon poly;
  poly.points = {{0, 0}, {4, 0}, {4, 4}, {0, 4}, {0, 0}, {1, 1}, {3, 1}, {3, 3}, {1, 3}, {1, 1}};
  render::Primitive p;
  p.type = render::ShapeType::polygon;
  render::shapes::set_up_polygon(p, poly);
  EXPECT_EQ(render::intersect_all(p, ray({0.5, 0.5, -2}, {0, 0, 1})).count, 1);
  EXPECT_EQ(render::intersect_all(p, ray({2, 2, -2}, {0, 0, 1})).count, 0);   // in the hole
  EXPECT_EQ(render::intersect_all(p, ray({5, 2, -2}, {0, 0, 1})).count, 0);
  EXPECT_NEAR(render::intersect_all(p, ray({3.5, 2, 3}, {0, 0, -1})).t[0], 3.0, 1e-12);
}

}  // namespace
}  // namespace povtrace::test

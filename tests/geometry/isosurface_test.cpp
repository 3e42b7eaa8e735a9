// Isosurface: functions with known surfaces (a sphere, two spheres, a plane) and seeded random rays. POV-Ray's
// search returns the far end of the first piece shorter than `accuracy` that ends inside, so a hit lies at most
// `accuracy` beyond the true crossing, never before it; normals are forward differences over `accuracy`. Also the
// closed container's faces, max_trace, the inside rule, rays leaving a hit, and the BVH against brute force.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <random>

#include "geometry_kit.hpp"
#include "parser/parse_scene.hpp"
#include "renderer/shapes/isosurface.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

Isosurface parsed(const std::string& body) {
  ParseOptions o;
  o.message_sink = [](const std::string&) {};
  const SceneDescription s = parse_scene_text("#version 3.7;\nisosurface { " + body + " }\n", "iso.pov", o);
  return std::get<Isosurface>(s.objects.at(0).shape);
}

// The entry and exit of the ray with the sphere |p − c| = r in world space (the sphere placed by m, which scales
// uniformly by k), or nothing.
bool sphere_crossings(const Ray& r, Vec3 c, double radius, double& t0, double& t1) {
  const Vec3 oc = r.origin - c;
  const double b = dot(oc, r.direction), disc = b * b - dot(oc, oc) + radius * radius;
  if (disc <= 0) return false;
  t0 = -b - std::sqrt(disc);
  t1 = -b + std::sqrt(disc);
  return true;
}

TEST(Isosurface, RandomRaysFindTheSphereWithinAccuracyBeyondIt) {
  const Isosurface iso = parsed("function { sqrt(x*x + y*y + z*z) - 0.8 } contained_by { box { -1, 1 } }");
  std::mt19937 rng(3141);
  std::uniform_real_distribution<double> pos(-5, 5), scale(0.5, 2.0);
  int hits = 0, seconds = 0;
  for (int k = 0; k < 2000; ++k) {
    const double s = scale(rng);
    const Vec3 centre{pos(rng) / 2, pos(rng) / 2, pos(rng) / 2};
    const Matrix m = Matrix::scaling({s, s, s}) * Matrix::rotation({pos(rng) * 30, pos(rng) * 30, 0}) *
                     Matrix::translation(centre);
    const Primitive p = make_isosurface(iso, m);
    const Vec3 origin = centre + random_unit(rng) * (3.0 * s);
    const Ray r = ray(origin, centre + random_unit(rng) * (0.7 * s) - origin);
    double t0 = 0, t1 = 0;
    const bool crosses = sphere_crossings(r, centre, 0.8 * s, t0, t1) && t1 - t0 > 0.05 * s;
    const std::optional<SurfaceHit> h = nearest_hit(p, r, tolerance::min_isect_depth, tolerance::bound_huge);
    const bool found = h.has_value();
    if (!crosses) continue;
    ++hits;
    ASSERT_TRUE(found) << "ray " << k;
    // The search measures its pieces in world depth, whatever the transform.
    EXPECT_GE(h->t, t0 - 1e-12) << "ray " << k;
    EXPECT_LT(h->t, t0 + 0.001) << "ray " << k;
    const Vec3 at = r.origin + r.direction * h->t;
    EXPECT_NEAR(dot(surface_normal(*h, at), normalize(at - centre)), 1.0, 1e-5) << "ray " << k;
    // Leaving the hit finds the far side, not the same surface again.
    const std::optional<SurfaceHit> next = nearest_hit(p, Ray{at, r.direction}, tolerance::min_isect_depth,
                                                       tolerance::bound_huge);
    ASSERT_TRUE(next);
    EXPECT_GE(next->t, t1 - h->t - 1e-12) << "ray " << k;
    EXPECT_LT(next->t, t1 - h->t + 0.001) << "ray " << k;
    ++seconds;
  }
  EXPECT_GT(hits, 1000);
  EXPECT_EQ(seconds, hits);
}

TEST(Isosurface, MaxTraceKeepsThatManyRoots) {
  // Two spheres along x: a ray along the axis crosses four times.
  const std::string two = "function { min(sqrt((x+1)*(x+1) + y*y + z*z), sqrt((x-1)*(x-1) + y*y + z*z)) - 0.5 } "
                          "contained_by { box { <-2, -1, -1>, <2, 1, 1> } }";
  for (const auto& [items, expected] : {std::pair<std::string, std::size_t>{"", 1}, {"max_trace 3", 3},
                                        {"all_intersections", 4}}) {
    const Primitive p = make_isosurface(parsed(two + " " + items), Matrix::identity());
    HitBuffer hits;
    collect_hits(p, ray({-5, 0.01, 0}, {1, 0, 0}), hits);
    ASSERT_EQ(hits.size(), expected) << items;
    std::sort(hits.begin(), hits.end(), [](auto& a, auto& b) { return a.t < b.t; });
    const double truth[4] = {3.5, 4.5, 5.5, 6.5};
    for (std::size_t i = 0; i < hits.size(); ++i) EXPECT_NEAR(hits[i].t, truth[i], 0.0011) << items;
  }
}

TEST(Isosurface, EvaluateRaisesATooLowMaxGradientAlongTheRay) {
  // 20·(|p| − 1): gradient 20 against max_gradient 0.5. From x = −2 to the container's far side x = 1.5 the function
  // falls from 20 to 10; both ends positive and 0.5·3.5 far below 30, so without evaluate the search gives up at
  // once. With evaluate 1, 10, 0.1 the bound (0.5, not above P0 = 1, so not lowered) is below the span's slope
  // (10/3.5 ≈ 2.9) times 10 and becomes 2.9·100 = 286: the sphere is found at x = −1, within accuracy beyond it.
  const std::string body = "function { 20 * (sqrt(x*x + y*y + z*z) - 1) } contained_by { box { <-2, -2, -2>, <1.5, 2, 2> } }"
                           " max_gradient 0.5";
  const Isosurface without = parsed(body), with = parsed(body + " evaluate 1, 10, 0.1");
  EXPECT_FALSE(without.evaluate);
  ASSERT_TRUE(with.evaluate);
  EXPECT_EQ(with.evaluate_params, (std::array<double, 3>{1, 10, 0.1}));
  HitBuffer hits;
  collect_hits(make_isosurface(without, Matrix::identity()), ray({-3, 0, 0}, {1, 0, 0}), hits);
  EXPECT_TRUE(hits.empty());
  collect_hits(make_isosurface(with, Matrix::identity()), ray({-3, 0, 0}, {1, 0, 0}), hits);
  ASSERT_EQ(hits.size(), 1u);
  EXPECT_GE(hits[0].t, 2.0);
  EXPECT_LE(hits[0].t, 2.0011);
  // Rays start from the bound learnt by the probe rays before rendering, not from what earlier rays of the render
  // left: the same ray gives the same hit however many came before. The probes met the slope 20 near the surface.
  const Primitive learnt = make_isosurface(with, Matrix::identity());
  EXPECT_GT(static_cast<const IsosurfaceData&>(*learnt.data).max_gradient, 20.0);
  EXPECT_EQ(static_cast<const IsosurfaceData&>(*make_isosurface(without, Matrix::identity()).data).max_gradient, 0.5);
  HitBuffer again;
  collect_hits(make_isosurface(with, Matrix::identity()), ray({-3, 0, 0}, {1, 0, 0}), again);
  ASSERT_EQ(again.size(), 1u);
  EXPECT_EQ(again[0].t, hits[0].t);
}

TEST(Isosurface, AClosedContainerShowsWhereTheFunctionIsInside) {
  // f = x − 0.3 < 0 left of x = 0.3: a ray entering the box's −x face there hits the container.
  const Primitive p = make_isosurface(parsed("function { x - 0.3 }"), Matrix::identity());
  std::optional<SurfaceHit> h;
  h = nearest_hit(p, ray({-5, 0.2, 0.1}, {1, 0, 0}), tolerance::min_isect_depth, 1e10);
  ASSERT_TRUE(h);
  EXPECT_EQ(h->t, 4.0);
  EXPECT_EQ(surface_normal(*h, {-1, 0.2, 0.1}), (Vec3{-1, 0, 0}));
  HitBuffer hits;
  collect_hits(p, ray({-5, 0.2, 0.1}, {1, 0, 0}), hits);
  EXPECT_EQ(hits.size(), 1u);   // the container face uses up max_trace 1
  hits.clear();
  collect_hits(make_isosurface(parsed("function { x - 0.3 } max_trace 2"), Matrix::identity()),
               ray({-5, 0.2, 0.1}, {1, 0, 0}), hits);
  ASSERT_EQ(hits.size(), 2u);   // the container face, then the plane (leaving the inside)
  std::sort(hits.begin(), hits.end(), [](auto& a, auto& b) { return a.t < b.t; });
  EXPECT_NEAR(hits[1].t, 5.3, 0.0011);
  const Primitive open = make_isosurface(parsed("function { x - 0.3 } open"), Matrix::identity());
  h = nearest_hit(open, ray({-5, 0.2, 0.1}, {1, 0, 0}), tolerance::min_isect_depth, 1e10);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 5.3, 0.0011);   // open: only the plane
  EXPECT_NEAR(surface_normal(*h, {0.3, 0.2, 0.1}).x, 1.0, 1e-9);
}

TEST(Isosurface, InsideIsWithinTheContainerWhereTheFunctionIsAtMostTheThreshold) {
  const Primitive p = make_isosurface(
      parsed("function { sqrt(x*x + y*y + z*z) } threshold 0.8 contained_by { sphere { <0.5, 0, 0>, 0.6 } }"),
      Matrix::scaling({2, 2, 2}));
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> pos(-2.5, 2.5);
  int insides = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 w{pos(rng), pos(rng), pos(rng)}, q = w * 0.5;
    const Vec3 c = q - Vec3{0.5, 0, 0};
    const bool expected = dot(c, c) <= 0.36 && length(q) <= 0.8;
    EXPECT_EQ(inside(p, w), expected) << k;
    insides += expected;
  }
  EXPECT_GT(insides, 50);
}

TEST(Isosurface, BvhEqualsBruteForce) {
  const Isosurface a = parsed("function { sqrt(x*x + y*y + z*z) - 0.8 } contained_by { sphere { 0, 0.9 } }");
  const Isosurface b = parsed("function { y - 0.2 * sin(4 * x) } contained_by { box { -1, 1 } } max_gradient 2");
  std::mt19937 rng(2718);
  std::uniform_real_distribution<double> pos(-20, 20), u(0, 1);
  std::vector<Primitive> prims;
  for (int k = 0; k < 150; ++k) {
    const Vec3 c{pos(rng), pos(rng), pos(rng)};
    Primitive p = k % 3 == 2 ? sphere(c, 0.5 + u(rng))
                             : make_isosurface(k % 3 ? a : b, random_transform(rng) * Matrix::translation(c));
    p.object = static_cast<std::uint32_t>(k);
    prims.push_back(p);
  }
  const Accelerator acc(prims);
  const int iso_hits = bvh_hits_equal_to_brute_force(acc, rng, pos, 1500, [](std::uint32_t primitive) {
    return primitive % 3 != 2;
  });
  EXPECT_GT(iso_hits, 30);
}

}  // namespace

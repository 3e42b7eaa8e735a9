// The accelerator with lathes, prisms and sors mixed in among spheres: closest hits equal brute force for seeded
// random rays.
#include <gtest/gtest.h>

#include <random>

#include "renderer/shapes/solid_shapes.hpp"
#include "sweep_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

Primitive random_sweep(std::mt19937& rng, int kind, const Matrix& m) {
  std::uniform_real_distribution<double> x(0.3, 1.2), u(0, 1);
  if (kind == 0) {
    Lathe l;
    l.spline = u(rng) < 0.5 ? SplineKind::cubic : SplineKind::quadratic;
    l.points = profile({{0, -0.3}, {0, 0}, {x(rng), 0.5}, {x(rng), 1}, {0, 1.5}, {0, 1.8}});
    return make_lathe(l, m);
  }
  if (kind == 1) {
    const std::vector<Point2> pts{{0, 0}, {x(rng), 0}, {x(rng), x(rng)}, {0, x(rng)}, {0, 0}};
    Prism p;
    p.conic = u(rng) < 0.5;
    p.height1 = 0.3;
    p.height2 = 0.3 + x(rng);
    p.segment_starts = std::make_shared<const std::vector<std::uint32_t>>(
        *prism_segment_starts(SplineKind::linear, pts));
    p.points = profile(pts);
    return make_prism(p, m);
  }
  Sor s;
  s.points = profile({{x(rng), -0.5}, {x(rng), 0}, {x(rng), 0.6}, {x(rng), 1.2}, {x(rng), 1.7}});
  return make_sor(s, m);
}

TEST(SweepBvh, ClosestHitEqualsBruteForce) {
  std::mt19937 rng(1701);
  std::uniform_real_distribution<double> pos(-30, 30), small(0.2, 2), u(0, 1);
  std::vector<Primitive> prims;
  for (int k = 0; k < 400; ++k) {
    const Vec3 c{pos(rng), pos(rng), pos(rng)};
    const Matrix m = u(rng) < 0.5 ? Matrix::translation(c) : random_transform(rng) * Matrix::translation(c);
    Primitive p = k % 4 == 3 ? sphere(c, small(rng)) : random_sweep(rng, k % 4, m);
    p.object = static_cast<std::uint32_t>(k);
    prims.push_back(p);
  }
  const Accelerator acc(prims);
  const int sweep_hits = bvh_hits_equal_to_brute_force(acc, rng, pos, 3000, [](std::uint32_t primitive) {
    return primitive % 4 != 3;
  });
  EXPECT_GT(sweep_hits, 100);
}

}  // namespace

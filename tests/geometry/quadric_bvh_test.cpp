// The accelerator with cylinders, cones, discs and tori mixed in among spheres and boxes: closest hits equal brute
// force for seeded random rays.
#include <gtest/gtest.h>

#include <random>

#include "quadric_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

TEST(QuadricBvh, ClosestHitEqualsBruteForce) {
  std::mt19937 rng(606);
  std::uniform_real_distribution<double> pos(-30, 30), small(0.2, 2), u(0, 1);
  std::vector<Primitive> prims;
  for (int k = 0; k < 600; ++k) {
    const Vec3 c{pos(rng), pos(rng), pos(rng)};
    const Matrix m = u(rng) < 0.5 ? Matrix::translation(c) : random_transform(rng) * Matrix::translation(c);
    Primitive p;
    switch (k % 6) {
      case 0: p = make_cylinder(Cylinder{{0, 0, 0}, random_unit(rng) * small(rng), small(rng), u(rng) < 0.3}, m); break;
      case 1: p = make_cone(Cone{{0, 0, 0}, small(rng), random_unit(rng) * 2, u(rng) < 0.3 ? 0 : small(rng), u(rng) < 0.3}, m); break;
      case 2: p = make_disc(Disc{{0, 0, 0}, random_unit(rng), small(rng), u(rng) < 0.5 ? 0.1 : 0}, m); break;
      case 3: p = make_torus(Torus{small(rng) + 0.5, 0.3, u(rng) < 0.2}, m); break;
      case 4: p = sphere(c, small(rng)); break;
      default: p = box(c, c + Vec3{small(rng), small(rng), small(rng)}); break;
    }
    p.object = static_cast<std::uint32_t>(k);
    prims.push_back(p);
  }
  prims.push_back(plane({0, 1, 0}, -40));
  const Accelerator acc(prims);
  const int hits = bvh_hits_equal_to_brute_force(acc, rng, pos, 4000, [&prims](std::uint32_t primitive) {
    return primitive != prims.size() - 1;
  });
  EXPECT_GT(hits, 500);
}

}  // namespace

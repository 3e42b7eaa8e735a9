// The accelerator with superellipsoids, height fields and blobs mixed in among spheres and boxes: closest hits equal brute force for
// seeded random rays.
#include <gtest/gtest.h>

#include <random>

#include "quadric_kit.hpp"
#include "renderer/shapes/height_field.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

TEST(SolidBvh, ClosestHitEqualsBruteForce) {
  std::mt19937 rng(707);
  std::uniform_real_distribution<double> pos(-30, 30), small(0.2, 2), expo(0.2, 3), u(0, 1);
  std::vector<Primitive> prims;
  for (int k = 0; k < 400; ++k) {
    const Vec3 c{pos(rng), pos(rng), pos(rng)};
    const Matrix m = u(rng) < 0.5 ? Matrix::translation(c) : random_transform(rng) * Matrix::translation(c);
    Primitive p;
    switch (k % 5) {
      case 4: {
        std::vector<BlobComponent> parts(2);
        for (auto& part : parts) part.radius2 = small(rng) * small(rng), part.strength = 1;
        parts[1].centre = random_unit(rng);
        Blob b;
        b.threshold = 0.3;
        b.components = std::make_shared<std::vector<BlobComponent>>(parts);
        p = make_blob(b, m);
        break;
      }
      case 0: p = make_superellipsoid(Superellipsoid{expo(rng), expo(rng)}, m); break;
      case 3: {
        std::vector<std::uint16_t> h(20);
        for (auto& v : h) v = static_cast<std::uint16_t>(65535 * u(rng));
        p = place_height_field(height_field_data(h, 5, 4, 0, k % 8 == 3), Matrix::scaling({3, 2, 3}) * m);
        break;
      }
      case 1: p = sphere(c, small(rng)); break;
      default: p = box(c, c + Vec3{small(rng), small(rng), small(rng)}); break;
    }
    p.object = static_cast<std::uint32_t>(k);
    prims.push_back(p);
  }
  const Accelerator acc(prims);
  const int solid_hits = bvh_hits_equal_to_brute_force(acc, rng, pos, 3000, [](std::uint32_t primitive) {
    return primitive % 5 == 0 || primitive % 5 >= 3;
  });
  EXPECT_GT(solid_hits, 100);
}

}  // namespace

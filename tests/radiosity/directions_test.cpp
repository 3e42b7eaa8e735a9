// The Halton(2,3) cosine-weighted direction pool against hand-computed entries and the means that POV-Ray's
// renders of a sky-only scene give (docs/issue19-study.md §5.2, §5.3).
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "renderer/radiosity/directions.hpp"

namespace povtrace::render::radiosity {
namespace {

TEST(RadicalInverse, MirrorsTheDigits) {
  EXPECT_EQ(radical_inverse(0, 2), 0.0);
  EXPECT_EQ(radical_inverse(1, 2), 0.5);
  EXPECT_EQ(radical_inverse(2, 2), 0.25);
  EXPECT_EQ(radical_inverse(3, 2), 0.75);
  EXPECT_EQ(radical_inverse(6, 2), 0.375);          // 110b → 0.011b
  EXPECT_DOUBLE_EQ(radical_inverse(1, 3), 1.0 / 3);
  EXPECT_DOUBLE_EQ(radical_inverse(2, 3), 2.0 / 3);
  EXPECT_DOUBLE_EQ(radical_inverse(3, 3), 1.0 / 9);
  EXPECT_DOUBLE_EQ(radical_inverse(5, 3), 2.0 / 3 + 1.0 / 9);   // 12 in base 3 → 0.21
}

void expect_direction(Vec3 d, Vec3 want) {
  EXPECT_NEAR(d.x, want.x, 5e-6);
  EXPECT_NEAR(d.y, want.y, 5e-6);
  EXPECT_NEAR(d.z, want.z, 5e-6);
}

TEST(DirectionPool, FirstEntriesByHand) {
  // k = 0: u = ½, v = ⅓ → ρ = √½, θ = 120°.
  expect_direction(halton_cosine_direction(0), {-0.35355, 0.70711, 0.61237});
  // k = 1: u = ¼, v = ⅔ → ρ = ½, θ = 240°.
  expect_direction(halton_cosine_direction(1), {-0.25, 0.86603, -0.43301});
  // k = 2: u = ¾, v = 1/9 → ρ = √¾, θ = 40°: x = 0.86603·cos 40°, z = 0.86603·sin 40°, y = ½.
  expect_direction(halton_cosine_direction(2), {0.66341, 0.5, 0.55667});
}

TEST(DirectionPool, EveryEntryIsAUnitVectorInTheUpperHemisphere) {
  const DirectionPool pool(1600);
  ASSERT_EQ(pool.size(), 1600u);
  for (const Vec3& d : pool.directions()) {
    EXPECT_NEAR(length(d), 1.0, 1e-12);
    EXPECT_GE(d.y, 0.0);
  }
}

// The means over the default pool (M = 1600) that POV-Ray's sky-only renders reproduce (study §5.3).
TEST(DirectionPool, MeansOverTheDefaultPool) {
  const DirectionPool pool(1600);
  double y = 0, x2 = 0, y8 = 0, wave = 0, quadrants = 0;
  for (const Vec3& d : pool.directions()) {
    y += d.y;
    x2 += d.x * d.x;
    y8 += std::pow(d.y, 8);
    wave += 0.5 + 0.5 * std::sin(9 * d.x + 7 * d.z);
    quadrants += d.z * d.x >= 0 ? 1 : 0;
  }
  const double n = 1600;
  EXPECT_NEAR(y / n, 0.66737, 5e-6);
  EXPECT_NEAR(x2 / n, 0.24935, 5e-6);
  EXPECT_NEAR(y8 / n, 0.20070, 5e-6);
  EXPECT_NEAR(wave / n, 0.49925, 5e-6);
  EXPECT_EQ(quadrants / n, 0.5);
}

TEST(DirectionPool, PrecomputedEntriesEqualTheGeneratorAndCycle) {
  const DirectionPool pool(100000);   // diffuse_back.pov's pool size
  EXPECT_EQ(pool.size(), 100000u);
  for (const std::size_t k : {0u, 1u, 1599u, 1600u, 65535u, 99999u}) EXPECT_EQ(pool[k], halton_cosine_direction(k));
  EXPECT_EQ(pool.cyclic(100000), pool[0]);
  EXPECT_EQ(pool.cyclic(200003), pool[3]);
}

TEST(DirectionPool, SmallPoolsArePrefixesOfTheSequence) {
  const DirectionPool small(7);
  for (std::size_t k = 0; k < 7; ++k) EXPECT_EQ(small[k], halton_cosine_direction(k));
  EXPECT_EQ(small.cyclic(7), small[0]);
  EXPECT_THROW(DirectionPool(0), std::invalid_argument);
}

}  // namespace
}  // namespace povtrace::render::radiosity

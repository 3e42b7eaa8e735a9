// Pool directions mapped onto a normal, and the rejection and fallback rule for perturbed normals
// (docs/issue19-study.md §4.2, §4.3).
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <numbers>
#include <vector>

#include "renderer/radiosity/frame.hpp"

namespace povtrace::render::radiosity {
namespace {

void expect_vec(Vec3 a, Vec3 b, double tol = 1e-12) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(Frame, NormalsNearPlusYUseThePoolAsIs) {
  const Vec3 d{0.1, 0.2, 0.3};
  EXPECT_EQ(make_frame({0, 1, 0}).kind, Frame::Kind::as_is);
  EXPECT_EQ(to_world(make_frame({0, 1, 0}), d), d);
  // 2° off +y is still within the shortcut (y = cos 2° > 0.999); 3° is not.
  const double a2 = 2 * std::numbers::pi / 180, a3 = 3 * std::numbers::pi / 180;
  EXPECT_EQ(to_world(make_frame({std::sin(a2), std::cos(a2), 0}), d), d);
  EXPECT_EQ(make_frame({std::sin(a3), std::cos(a3), 0}).kind, Frame::Kind::rotated);
}

TEST(Frame, NormalsNearMinusYNegateThePool) {
  const Vec3 d{0.1, 0.2, 0.3};
  EXPECT_EQ(make_frame({0, -1, 0}).kind, Frame::Kind::negated);
  EXPECT_EQ(to_world(make_frame({0, -1, 0}), d), -d);
  const double a = 2 * std::numbers::pi / 180;
  EXPECT_EQ(to_world(make_frame({0, -std::cos(a), std::sin(a)}), d), -d);
}

TEST(Frame, NormalsNearZUseTheYHelper) {
  // n = +z: axis_x = normalise(z × y) = −x, axis_z = (−x) × z = +y, so (x, y, z) ↦ (−x, z, y).
  const Frame f = make_frame({0, 0, 1});
  EXPECT_EQ(f.kind, Frame::Kind::rotated);
  expect_vec(f.axis_x, {-1, 0, 0});
  expect_vec(f.axis_z, {0, 1, 0});
  expect_vec(to_world(f, {0.1, 0.2, 0.3}), {-0.1, 0.3, 0.2});
  // n = −z: axis_x = (−z) × y = +x, axis_z = x × (−z) = +y, so (x, y, z) ↦ (x, z, −y).
  expect_vec(to_world(make_frame({0, 0, -1}), {0.1, 0.2, 0.3}), {0.1, 0.3, -0.2});
}

TEST(Frame, OtherNormalsUseTheZHelper) {
  // n = (0, 0.6, 0.8): |n.z| ≤ 0.9, so axis_x = normalise(n × z) = +x and axis_z = x × n = (0, −0.8, 0.6).
  const Frame f = make_frame({0, 0.6, 0.8});
  expect_vec(f.axis_x, {1, 0, 0});
  expect_vec(f.axis_z, {0, -0.8, 0.6});
  expect_vec(to_world(f, {0, 1, 0}), {0, 0.6, 0.8});
}

TEST(Frame, GenericNormalGivesAnOrthonormalFrameAndKeepsTheCosine) {
  const Vec3 n = normalize(Vec3{0.3, -0.5, 0.81});
  const Frame f = make_frame(n);
  EXPECT_EQ(f.kind, Frame::Kind::rotated);
  EXPECT_NEAR(length(f.axis_x), 1, 1e-14);
  EXPECT_NEAR(length(f.axis_z), 1, 1e-14);
  EXPECT_NEAR(dot(f.axis_x, n), 0, 1e-14);
  EXPECT_NEAR(dot(f.axis_z, n), 0, 1e-14);
  EXPECT_NEAR(dot(f.axis_x, f.axis_z), 0, 1e-14);
  const DirectionPool pool(200);
  for (const Vec3& d : pool.directions()) {
    const Vec3 w = to_world(f, d);
    EXPECT_NEAR(length(w), 1, 1e-12);
    EXPECT_NEAR(dot(w, n), d.y, 1e-12);   // the pool's y is the cosine to the normal
  }
}

TEST(Frame, SimilarNormals) {
  EXPECT_TRUE(similar_normals({0, 1, 0}, {0, 1, 0}));
  EXPECT_TRUE(similar_normals({0, 1, 0}, {3e-11, 1 - 3e-11, 3e-11}));
  EXPECT_FALSE(similar_normals({0, 1, 0}, {4e-11, 1 - 4e-11, 4e-11}));
}

TEST(SampleDirections, RawNormalTakesConsecutiveEntries) {
  const DirectionPool pool(16);
  std::size_t cursor = 14;
  const Vec3 n = normalize(Vec3{1, 2, 3});
  SampleDirections s(pool, cursor, 5, n, n);
  ASSERT_EQ(s.count(), 5u);
  const Frame f = make_frame(n);
  for (const std::size_t k : {14u, 15u, 0u, 1u, 2u}) EXPECT_EQ(s.next(), to_world(f, pool[k]));
  EXPECT_EQ(cursor, 3u);
  EXPECT_EQ(s.raw_rays(), 5u);
  EXPECT_EQ(s.layer_rays(), 0u);
  EXPECT_TRUE(s.file_under_raw());
}

TEST(SampleDirections, RayCountIsCappedAtThePoolSize) {
  const DirectionPool pool(8);
  std::size_t cursor = 0;
  const SampleDirections s(pool, cursor, 35, {0, 1, 0}, {0, 1, 0});
  EXPECT_EQ(s.count(), 8u);
}

// The rule restated independently: entries in order, rejected below the raw surface, 5n tries (≤ M), then the
// raw frame for the rest.
struct Expected {
  std::vector<Vec3> directions;
  std::size_t raw_rays = 0;
  std::size_t cursor = 0;
};
Expected expected_directions(const DirectionPool& pool, std::size_t n, Vec3 raw, Vec3 layer) {
  Expected e;
  const Frame perturbed = make_frame(layer), plain = make_frame(raw);
  std::size_t budget = std::min(5 * n, pool.size());
  while (e.directions.size() < n && budget > 0) {
    const Vec3 d = to_world(perturbed, pool.cyclic(e.cursor++));
    --budget;
    if (dot(d, raw) > 0) e.directions.push_back(d);
  }
  while (e.directions.size() < n) {
    e.directions.push_back(to_world(plain, pool.cyclic(e.cursor++)));
    ++e.raw_rays;
  }
  return e;
}

void expect_sequence(const DirectionPool& pool, std::size_t n, Vec3 raw, Vec3 layer) {
  const Expected want = expected_directions(pool, n, raw, layer);
  std::size_t cursor = 0;
  SampleDirections s(pool, cursor, n, raw, layer);
  for (const Vec3& d : want.directions) EXPECT_EQ(s.next(), d);
  EXPECT_EQ(cursor, want.cursor % pool.size());
  EXPECT_EQ(s.raw_rays(), want.raw_rays);
  EXPECT_EQ(s.layer_rays(), n - want.raw_rays);
}

TEST(SampleDirections, PerturbedNormalRejectsDirectionsBelowTheRawSurface) {
  const DirectionPool pool(1600);
  const Vec3 raw{0, 1, 0}, layer = normalize(Vec3{1, 1, 0});   // tilted by 45°
  const Expected want = expected_directions(pool, 50, raw, layer);
  ASSERT_GT(want.cursor, 50u);         // some entries were rejected
  ASSERT_EQ(want.raw_rays, 0u);        // but the budget sufficed
  expect_sequence(pool, 50, raw, layer);
  std::size_t cursor = 0;
  SampleDirections s(pool, cursor, 50, raw, layer);
  for (int i = 0; i < 50; ++i) EXPECT_GT(dot(s.next(), raw), 0);
  EXPECT_FALSE(s.file_under_raw());
}

TEST(SampleDirections, OppositeNormalFallsBackAfterFiveNTries) {
  // Every direction around −y lies below the raw surface: 5n = 50 entries are rejected, then the raw frame
  // (+y, pool as is) shoots all 10 rays with entries 50…59.
  const DirectionPool pool(1600);
  std::size_t cursor = 0;
  SampleDirections s(pool, cursor, 10, {0, 1, 0}, {0, -1, 0});
  for (std::size_t k = 50; k < 60; ++k) EXPECT_EQ(s.next(), pool[k]);
  EXPECT_EQ(cursor, 60u);
  EXPECT_EQ(s.raw_rays(), 10u);
  EXPECT_TRUE(s.file_under_raw());
}

TEST(SampleDirections, SteepPerturbationMixesBothFrames) {
  const DirectionPool pool(1600);
  const Vec3 raw{0, 1, 0}, layer = normalize(Vec3{1, -1.2, 0});   // 140° from the raw normal
  const Expected want = expected_directions(pool, 20, raw, layer);
  ASSERT_GT(want.raw_rays, 0u);
  ASSERT_LT(want.raw_rays, 20u);
  expect_sequence(pool, 20, raw, layer);
}

TEST(SampleDirections, TriesAreCappedAtThePoolSize) {
  // M = 8, n = 4: 5n = 20 tries would exceed the pool, so only 8 are tried before the fallback.
  const DirectionPool pool(8);
  std::size_t cursor = 0;
  SampleDirections s(pool, cursor, 4, {0, 1, 0}, {0, -1, 0});
  for (const std::size_t k : {0u, 1u, 2u, 3u}) EXPECT_EQ(s.next(), pool[k]);   // entries 8…11 cycle to 0…3
  EXPECT_EQ(cursor, 4u);
}

}  // namespace
}  // namespace povtrace::render::radiosity

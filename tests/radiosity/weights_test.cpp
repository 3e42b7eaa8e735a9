// Validity and weight of a cached sample for a query, and the query's error bound (docs/issue19-study.md
// §3.2–3.4), branch by branch with hand-computed values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "renderer/radiosity/weights.hpp"

namespace povtrace::render::radiosity {
namespace {

// A sample at the origin on the plane y = 0, radius 1, nearest hit 0.5 away along +x.
SampleGeometry sample() {
  SampleGeometry s;
  s.point = {0, 0, 0};
  s.normal = {0, 1, 0};
  s.to_nearest = {1, 0, 0};
  s.radius = 1;
  s.nearest = 0.5f;
  s.quality = 1;
  s.depth = 0;
  s.pass = 1;
  s.tile = 3;
  return s;
}

Query query(Vec3 p, double e, bool final_pass = false) {
  Query q;
  q.point = p;
  q.normal = {0, 1, 0};
  q.error_bound = e;
  q.depth = 0;
  q.final_pass = final_pass;
  return q;
}

TEST(RadiosityWeight, EffectiveRadiusShrinksTowardsTheNearestHit) {
  const SampleGeometry s = sample();
  EXPECT_EQ(effective_radius(s, {0, 0, 0.5}), 1.0);       // perpendicular to the nearest hit: c = 0
  EXPECT_EQ(effective_radius(s, {-0.5, 0, 0}), 1.0);      // away from it: c < 0
  EXPECT_EQ(effective_radius(s, {0.5, 0, 0}), 0.5);       // towards it: c = 1, ρ = r_min
  EXPECT_NEAR(effective_radius(s, {0.3, 0, 0.4}), 0.7, 1e-15);   // c = 0.6: 0.6·0.5 + 0.4·1
  EXPECT_EQ(effective_radius(s, {5e-7, 0, 0}), 1.0);      // within 1e−6 of the sample: no direction
}

TEST(RadiosityWeight, ErrorIsDistanceOverRadiusPlusNormalTerm) {
  const SampleGeometry s = sample();
  EXPECT_NEAR(reuse_error(s, {0, 0, 0.5}, {0, 1, 0}, 1.0), 0.5, 1e-15);
  // Normals 60° apart: 2·√(1 − ½) = √2.
  const Vec3 n60{std::sin(std::numbers::pi / 3), std::cos(std::numbers::pi / 3), 0};
  EXPECT_NEAR(reuse_error(s, {0, 0, 0}, n60, 1.0), std::sqrt(2.0), 1e-12);
}

TEST(RadiosityWeight, LinearInThePretrace) {
  // ℓ = 0.36, ρ = 1, E = 1.8: t = 0.2, w = 0.8.
  EXPECT_NEAR(sample_weight(query({0, 0, 0.36}, 1.8), sample()), 0.8, 1e-12);
  // Normal term only: w = 1 − √2/1.8.
  Query q = query({0, 0, 0}, 1.8);
  q.normal = {std::sin(std::numbers::pi / 3), std::cos(std::numbers::pi / 3), 0};
  EXPECT_NEAR(sample_weight(q, sample()), 1 - std::sqrt(2.0) / 1.8, 1e-12);
}

TEST(RadiosityWeight, PseudoSigmoidInTheFinalPassAtDepthZero) {
  EXPECT_EQ(smooth_weight(0.25), 0.875);
  EXPECT_EQ(smooth_weight(0.75), 0.125);
  EXPECT_EQ(smooth_weight(0.5), 0.5);
  EXPECT_EQ(smooth_weight(0), 1.0);
  EXPECT_NEAR(sample_weight(query({0, 0, 0.25}, 1.0, true), sample()), 0.875, 1e-12);
  EXPECT_NEAR(sample_weight(query({0, 0, 0.75}, 1.0, true), sample()), 0.125, 1e-12);
  // Bounces stay linear in the final pass.
  SampleGeometry deep = sample();
  deep.depth = 1;
  Query q = query({0, 0, 0.25}, 1.0, true);
  q.depth = 1;
  EXPECT_NEAR(sample_weight(q, deep), 0.75, 1e-12);
}

TEST(RadiosityWeight, QuickTestUsesTheStoredRadius) {
  // r = 1 clamped below a nearest hit at 3: towards the hit ρ = 3, but the quick test ℓ < r·E still applies.
  SampleGeometry s = sample();
  s.nearest = 3;
  EXPECT_EQ(effective_radius(s, {2, 0, 0}), 3.0);
  EXPECT_EQ(sample_weight(query({2, 0, 0}, 1.8), s), 0.0);                    // 2 ≥ 1·1.8
  EXPECT_NEAR(sample_weight(query({1.7, 0, 0}, 1.8), s), 1 - (1.7 / 3) / 1.8, 1e-12);
}

TEST(RadiosityWeight, EffectiveRadiusLimitsTheDistance) {
  // Towards the nearest hit ρ = 0.5: ℓ = 0.95 passes the quick test (< 1.8) but not ℓ < ρ·E = 0.9.
  EXPECT_EQ(sample_weight(query({0.95, 0, 0}, 1.8), sample()), 0.0);
  EXPECT_NEAR(sample_weight(query({0.45, 0, 0}, 1.8), sample()), 1 - 0.9 / 1.8, 1e-12);
}

TEST(RadiosityWeight, ErrorMustStayBelowTheBound) {
  // ℓ/ρ = 0.5 plus the 60° normal term √2 = 1.914 ≥ 1.8.
  Query q = query({0, 0, 0.5}, 1.8);
  q.normal = {std::sin(std::numbers::pi / 3), std::cos(std::numbers::pi / 3), 0};
  EXPECT_EQ(sample_weight(q, sample()), 0.0);
}

// A query at distance ℓ from the sample whose direction has y-component f (normals both +y, so in_front = f).
Vec3 at_height(double l, double f) { return Vec3{0, f, std::sqrt(1 - f * f)} * l; }

TEST(RadiosityWeight, InFrontFadeAndCutOff) {
  const SampleGeometry s = sample();
  EXPECT_NEAR(in_front(s, at_height(0.36, -0.025), {0, 1, 0}), -0.025, 1e-15);
  EXPECT_EQ(in_front_fade(-0.025), 0.5);
  EXPECT_EQ(in_front_fade(0), 1.0);
  EXPECT_NEAR(sample_weight(query(at_height(0.36, -0.025), 1.8), s), 0.8 * 0.5, 1e-12);
  EXPECT_NEAR(sample_weight(query(at_height(0.36, 0.3), 1.8), s), 0.8, 1e-12);   // behind: no fade
  EXPECT_EQ(sample_weight(query(at_height(0.36, -0.05), 1.8), s), 0.0);          // f ≤ −0.05: rejected
  EXPECT_EQ(sample_weight(query(at_height(0.36, -0.2), 1.8), s), 0.0);
  EXPECT_EQ(in_front(s, {0, -5e-7, 0}, {0, 1, 0}), 1.0);                          // at the point
}

TEST(RadiosityWeight, OppositeNormalsAreRejectedUnlessAtThePoint) {
  // At depth 1 E can exceed 2√2, the normal term of opposite normals. Their half vector is zero: POV-Ray's
  // in-front value is NaN and the sample is not used, except within 1e−6 where in_front is 1.
  SampleGeometry s = sample();
  s.depth = 1;
  Query q = query({0, 0, 0.01}, 4.0);
  q.depth = 1;
  q.normal = {0, -1, 0};
  EXPECT_TRUE(std::isnan(in_front(s, q.point, q.normal)));
  EXPECT_EQ(sample_weight(q, s), 0.0);
  q.point = {0, 0, 0};
  EXPECT_NEAR(sample_weight(q, s), 1 - 2 * std::sqrt(2.0) / 4, 1e-12);
}

TEST(RadiosityWeight, QualityScalesAfterTheSmallWeightCut) {
  SampleGeometry s = sample();
  s.quality = 0.5f;
  EXPECT_NEAR(sample_weight(query({0, 0, 0.36}, 1.8), s), 0.4, 1e-12);
  // w = 1 − 0.9985 = 0.0015 > 0.001 is kept, then halved below the cut.
  EXPECT_NEAR(sample_weight(query({0, 0, 0.9985}, 1.0), s), 0.00075, 1e-12);
  // w = 0.0009 ≤ 0.001 is dropped.
  EXPECT_EQ(sample_weight(query({0, 0, 0.9991}, 1.0), sample()), 0.0);
}

TEST(RadiosityWeight, DepthExclusion) {
  SampleGeometry s = sample();   // pass 1, tile 3
  Query q = query({0, 0, 0.36}, 1.8);
  EXPECT_TRUE(sample_visible(q, s));                   // made in another tile: the store decides
  EXPECT_GT(sample_weight(q, s), 0.0);
  q.depth = 1;
  EXPECT_FALSE(sample_visible(q, s));                  // another bounce depth
  EXPECT_EQ(sample_weight(q, s), 0.0);
}

TEST(RadiosityQuery, ErrorBound) {
  EXPECT_DOUBLE_EQ(query_error_bound(1.8, 0.5, true, 1.0, 0), 0.9);
  EXPECT_DOUBLE_EQ(query_error_bound(1.8, 0.5, false, 1.0, 0), 1.8);
  EXPECT_DOUBLE_EQ(query_error_bound(1.8, 0.5, false, 0.25, 0), 1.8);    // not below 0.25: no widening
  EXPECT_DOUBLE_EQ(query_error_bound(1.8, 0.5, false, 0.1, 0), 1.95);    // + (0.25 − 0.1)
  EXPECT_DOUBLE_EQ(query_error_bound(1.8, 0.5, true, 0.2, 2), 3.8);      // (0.9 + 0.05)·4
  EXPECT_DOUBLE_EQ(query_error_bound(1.8, 0.5, false, 1.0, 1), 3.6);
}

TEST(RadiosityQuery, ReuseCountPerDepth) {
  EXPECT_EQ(reuse_count(5, 0), 5);
  EXPECT_EQ(reuse_count(5, 1), 2);
  EXPECT_EQ(reuse_count(1, 1), 1);
  EXPECT_EQ(reuse_count(5, 2), 1);
  EXPECT_EQ(reuse_count(20, 7), 1);
}

TEST(RadiosityQuery, ReuseOrGather) {
  EXPECT_TRUE(reuse_is_enough(1.25, 5, false, false));    // 4·1.25 = 5 ≥ 5
  EXPECT_FALSE(reuse_is_enough(1.2, 5, false, false));
  EXPECT_TRUE(reuse_is_enough(1.2, 5, true, false));      // final pass: any positive weight
  EXPECT_FALSE(reuse_is_enough(1.2, 5, true, true));      // unless always_sample
  EXPECT_FALSE(reuse_is_enough(0, 5, true, false));
  EXPECT_FLOAT_EQ(quality_after_query(1.0f, 0.5, 5), 0.4f);
  EXPECT_FLOAT_EQ(quality_after_query(0.3f, 2.0, 5), 0.3f);
}

}  // namespace
}  // namespace povtrace::render::radiosity

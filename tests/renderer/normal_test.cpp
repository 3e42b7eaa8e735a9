// Normal perturbation at hand-computed points (pattern normals, ripples and waves with given sources, the
// transforms and no_bump_scale), and properties of the noise-based normals, which cannot match POV-Ray's point by
// point because its noise table is not ours.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "runtime/noise.hpp"
#include "renderer/pattern/normal_perturbation.hpp"

namespace povtrace::render {
namespace {

RenderNormal make(NormalKind kind, const Matrix& world_from_pattern = Matrix::identity(), double amount = 0.5) {
  Normal n;
  n.kind = kind;
  n.has_type = true;
  n.amount = amount;
  n.pattern.pattern = PatternKind::gradient;
  n.pattern.world_from_pattern = world_from_pattern;
  return build_render_normal(n);
}

void expect_direction(Vec3 actual, Vec3 expected, double tolerance = 1e-8) {
  const Vec3 e = normalize(expected);
  EXPECT_NEAR(actual.x, e.x, tolerance);
  EXPECT_NEAR(actual.y, e.y, tolerance);
  EXPECT_NEAR(actual.z, e.z, tolerance);
}

// gradient x sampled at the tetrahedron's vertices: Σ vᵢ·(x + a·vᵢ.x)·(−5·amount) = −5·amount·a·(4/3, 0, 0) plus
// x·Σvᵢ (zero up to POV-Ray's nine decimals); with amount ½ and a = 0.02 the normal tilts by −1/15 along x.
TEST(NormalPerturbation, GradientNormalTiltsByItsSlope) {
  const RenderNormal n = make(NormalKind::pattern);
  expect_direction(perturb_normal(n, {0, 1, 0}, {0.5, 0, 0.3}, {}), {-1.0 / 15.0, 1, 0}, 1e-7);
}

TEST(NormalPerturbation, AccuracyDoesNotChangeTheSlopeOfALinearPattern) {
  Normal d;
  d.kind = NormalKind::pattern;
  d.has_type = true;
  d.pattern.pattern = PatternKind::gradient;
  d.accuracy = 0.1;
  expect_direction(perturb_normal(build_render_normal(d), {0, 1, 0}, {0.3, 0, 0}, {}), {-1.0 / 15.0, 1, 0}, 1e-7);
}

// scale x 2 halves the pattern's slope in world space: the pattern-space normal (−1/15, 1, 0) goes back through
// the inverse transpose diag(½, 1, 1).
TEST(NormalPerturbation, ScaledNormalComesBackThroughTheInverseTranspose) {
  const RenderNormal n = make(NormalKind::pattern, Matrix::scaling({2, 1, 1}));
  expect_direction(perturb_normal(n, {0, 1, 0}, {1.0, 0, 0}, {}), {-1.0 / 30.0, 1, 0}, 1e-7);
}

// With no_bump_scale the normal is not normalised in pattern space: after scale ½ it is (0, ½, 0) there, so the
// same bend counts twice as much.
TEST(NormalPerturbation, NoBumpScaleLetsAUniformScaleChangeTheBumps) {
  Normal d;
  d.kind = NormalKind::pattern;
  d.has_type = true;
  d.pattern.pattern = PatternKind::gradient;
  d.pattern.world_from_pattern = Matrix::scaling({0.5, 0.5, 0.5});
  expect_direction(perturb_normal(build_render_normal(d), {0, 1, 0}, {0.25, 0, 0}, {}), {-1.0 / 15.0, 1, 0}, 1e-7);
  d.no_bump_scale = true;
  expect_direction(perturb_normal(build_render_normal(d), {0, 1, 0}, {0.25, 0, 0}, {}), {-2.0 / 15.0, 1, 0}, 1e-7);
}

// ripples with one source at the origin: at distance ⅛ the sine of a turn's eighth pushes the normal away from the
// source by amount·sin(π/4). waves divide the phase by the source's frequency and multiply the index by it.
TEST(NormalPerturbation, RipplesAndWavesAtHandComputedPoints) {
  const std::vector<WaveSource> sources = {WaveSource{{0, 0, 0}, 2.0}};
  expect_direction(perturb_normal(make(NormalKind::ripples), {0, 1, 0}, {0.125, 0, 0}, sources),
                   {0.5 * std::sin(std::numbers::pi / 4), 1, 0});
  expect_direction(perturb_normal(make(NormalKind::waves), {0, 1, 0}, {0.125, 0, 0}, sources), {0.25, 1, 0});
}

TEST(NormalPerturbation, WaveSourceFrequenciesAreThoseOfPovRaysGenerator) {
  const std::vector<WaveSource> w = make_wave_sources(3);
  ASSERT_EQ(w.size(), 3u);
  EXPECT_NEAR(w[0].frequency, 0.9191158787805639, 1e-15);
  EXPECT_NEAR(w[1].frequency, 0.96004119998788, 1e-15);
  EXPECT_NEAR(w[2].frequency, 0.43316965239421595, 1e-15);
  for (const WaveSource& s : w) EXPECT_NEAR(length(s.centre), 1.0, 1e-12);
}

TEST(NormalPerturbation, SlopeMapIsAHermiteCubicBetweenEntries) {
  Normal d;
  d.kind = NormalKind::pattern;
  d.has_type = true;
  d.pattern.pattern = PatternKind::gradient;
  d.slope_map = {{0, 0, 1}, {1, 1, 1}};   // height = value, slope 1 at both ends: the straight line
  const RenderNormal n = build_render_normal(d);
  EXPECT_NEAR(slope_value(n, {0.3, 0, 0}), 0.3, 1e-12);
  d.slope_map = {{0, 0, 0}, {1, 1, 0}};   // flat ends: 3t² − 2t³
  EXPECT_NEAR(slope_value(build_render_normal(d), {0.25, 0, 0}), 3 * 0.0625 - 2 * 0.015625, 1e-12);
}

// Statistics of the noise-based normals over many points of a plane: bumps tilt both ways around the surface
// normal on average; dents never bend more than bumps (noise³ ≤ 1 scales the same vector noise); wrinkles add
// absolute values, so they lean toward +x and +z everywhere (a bias POV-Ray's wrinkles have too).
TEST(NormalPerturbation, NoiseNormalStatistics) {
  const RenderNormal bumps = make(NormalKind::bumps), dents = make(NormalKind::dents),
                     wrinkles = make(NormalKind::wrinkles);
  Vec3 bump_mean{0, 0, 0};
  double bump_tilt = 0;
  int dents_within = 0, wrinkles_positive = 0;
  constexpr int kSide = 60;
  for (int i = 0; i < kSide; ++i)
    for (int j = 0; j < kSide; ++j) {
      const Vec3 p{i * 0.37 + 0.11, 0.2, j * 0.29 + 0.05};
      const Vec3 b = perturb_normal(bumps, {0, 1, 0}, p, {});
      bump_mean += b;
      bump_tilt += std::acos(std::clamp(b.y, -1.0, 1.0));
      const Vec3 d = perturb_normal(dents, {0, 1, 0}, p, {});
      if (d.y >= b.y - 1e-12) ++dents_within;
      const Vec3 w = perturb_normal(wrinkles, {0, 1, 0}, p, {});
      if (w.x >= 0 && w.z >= 0) ++wrinkles_positive;
    }
  const double count = kSide * kSide;
  bump_mean = bump_mean / count;
  EXPECT_LT(std::fabs(bump_mean.x), 0.05);
  EXPECT_LT(std::fabs(bump_mean.z), 0.05);
  const double mean_tilt = bump_tilt / count;   // amount ½ of noise components of about ±0.3 typical
  EXPECT_GT(mean_tilt, 0.05);
  EXPECT_LT(mean_tilt, 0.5);
  EXPECT_EQ(dents_within, kSide * kSide);
  EXPECT_EQ(wrinkles_positive, kSide * kSide);
}

}  // namespace
}  // namespace povtrace::render

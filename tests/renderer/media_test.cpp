// Media integration (renderer/media/): the chi-square thresholds, the lit intervals lights make along a ray, and
// what constant media do to a segment (POV-Ray 3.7's interior/media.cpp, docs/issue20-media-study.md).
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/media/media_integrator.hpp"
#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

// Quantiles of the chi-square distribution (P(X > x) = q): for even degrees of freedom, the values of statistical
// tables; for odd ones below 26, POV-Ray 3.7.0.10's chdtri (its log-gamma of half-integers is 0.0396 too large), as
// computed by its chi2.cpp, which media and focal blur thresholds must equal.
TEST(MediaThresholds, InverseChiSquareMatchesPovRaysChdtri) {
  EXPECT_NEAR(inverse_chi_square_complement(2, 0.5), 2.0 * std::log(2.0), 1e-12);   // exponential with mean 2
  EXPECT_NEAR(inverse_chi_square_complement(4, 0.05), 9.4877290367811575, 1e-9);
  EXPECT_NEAR(inverse_chi_square_complement(36, 0.975), 21.335881560799049, 1e-9);
  EXPECT_NEAR(inverse_chi_square_complement(27, 0.9), 18.113895966895974, 1e-9);   // 13.5: POV-Ray's exact path
  // Odd, below 26: POV-Ray's values, not the tables' (0.0157908, 4.168159, 7.041505, 6.345811, 5.008751).
  EXPECT_NEAR(inverse_chi_square_complement(1, 0.9), 0.017098659305515445, 1e-12);
  EXPECT_NEAR(inverse_chi_square_complement(9, 0.9), 4.2253572226957417, 1e-9);
  EXPECT_NEAR(inverse_chi_square_complement(13, 0.9), 7.1180896824953637, 1e-9);
  EXPECT_NEAR(inverse_chi_square_complement(7, 0.5), 6.5261882819763368, 1e-9);
  EXPECT_NEAR(inverse_chi_square_complement(13, 0.975), 5.0537427309874206, 1e-9);
  EXPECT_NEAR(inverse_chi_square_complement(25, 0.9), 16.594758427406472, 1e-9);
  EXPECT_NEAR(inverse_chi_square_complement(3, 0.5), 2.4750414269371719, 1e-9);
}

// Media::PostProcess: thresholds scaled so that max_samples − 1 degrees of freedom give `variance`.
TEST(MediaThresholds, ScaledToTheVarianceAtMaxSamples) {
  Media m;
  m.min_samples = 3;
  m.max_samples = 9;
  m.variance = 0.01;
  const RenderMedia r = build_render_media(m, nullptr, false);
  ASSERT_EQ(r.sample_threshold.size(), 9u);
  EXPECT_NEAR(r.sample_threshold[7], 0.01, 1e-12);
  EXPECT_LT(r.sample_threshold[0], r.sample_threshold[1]);
}

std::vector<RenderLight> lights_of(const std::vector<Light>& lights) {
  SceneDescription s = base_scene();
  s.lights = lights;
  return build_render_scene(s, BuildOptions{}).lights;
}

TEST(MediaLitIntervals, PointLightsLightTheWholeSegment) {
  const MediaSegment seg{{0, 0, 0}, {1, 0, 0}, 20.0, false};
  const auto lit = lit_intervals(seg, lights_of({point_light({0, 10, 0})}));
  ASSERT_EQ(lit.size(), 1u);
  EXPECT_TRUE(lit[0].lit);
  EXPECT_EQ(lit[0].s1, 20.0);
}

// POV-Ray's shadowless lights (FILL_LIGHT_SOURCE) and lights with media_interaction off light no media.
TEST(MediaLitIntervals, ShadowlessAndNonInteractingLightsLightNothing) {
  Light shadowless = point_light({0, 10, 0});
  shadowless.shadowless = true;
  Light off = point_light({0, 10, 0});
  off.media_interaction = false;
  const MediaSegment seg{{0, 0, 0}, {1, 0, 0}, 20.0, false};
  const auto lit = lit_intervals(seg, lights_of({shadowless, off}));
  ASSERT_EQ(lit.size(), 1u);
  EXPECT_FALSE(lit[0].lit);
}

// A spotlight 10 above the ray pointing down with falloff 30° lights the ray where it is inside the cone:
// |x| ≤ 10·tan 30°.
TEST(MediaLitIntervals, SpotlightLightsItsCone) {
  Light spot = point_light({0, 10, 0});
  spot.spotlight = true;
  spot.point_at = {0, 0, 0};
  spot.radius = 20;
  spot.falloff = 30;
  const MediaSegment seg{{-10, 0, 0}, {1, 0, 0}, 20.0, false};
  const auto lit = lit_intervals(seg, lights_of({spot}));
  ASSERT_EQ(lit.size(), 3u);
  const double half = 10.0 * std::tan(30.0 * M_PI / 180.0);
  EXPECT_FALSE(lit[0].lit);
  EXPECT_TRUE(lit[1].lit);
  EXPECT_NEAR(lit[1].s0, 10.0 - half, 1e-9);
  EXPECT_NEAR(lit[1].s1, 10.0 + half, 1e-9);
  EXPECT_FALSE(lit[2].lit);
  EXPECT_EQ(lit[2].s1, 20.0);
}

class NoLight : public MediaLighting {
 public:
  std::optional<Arrival> arrival(std::size_t, Vec3) override { return std::nullopt; }
};

MediaEffect integrate(const Media& m, double depth, bool shadow_ray = false) {
  const RenderMedia r = build_render_media(m, nullptr, false);
  MediaSet set;
  set.media.push_back(r);
  MediaList list;
  list.add(set);
  NoLight none;
  MediaRandom random(1);
  return integrate_media(list, MediaSegment{{0, 0, 0}, {0, 0, 1}, depth, shadow_ray}, {}, none, random);
}

TEST(MediaIntegration, ConstantAbsorptionFollowsBeersLaw) {
  Media m;
  m.absorption = Colour{0.5, 0.25, 0.0, 0, 0};
  for (int method : {1, 2, 3}) {
    m.method = method;
    const MediaEffect e = integrate(m, 2.0);
    EXPECT_NEAR(e.transmittance.x, std::exp(-1.0), 1e-12) << method;
    EXPECT_NEAR(e.transmittance.y, std::exp(-0.5), 1e-12) << method;
    EXPECT_EQ(e.transmittance.z, 1.0) << method;
    EXPECT_EQ(e.emitted, (Vec3{0, 0, 0})) << method;
  }
}

TEST(MediaIntegration, ConstantEmissionAddsEmissionTimesLength) {
  Media m;
  m.emission = Colour{0.25, 0.5, 1.0, 0, 0};
  const MediaEffect e = integrate(m, 3.0);
  EXPECT_NEAR(e.emitted.x, 0.75, 1e-12);
  EXPECT_NEAR(e.emitted.z, 3.0, 1e-12);
  EXPECT_EQ(e.transmittance, (Vec3{1, 1, 1}));
}

// Shadow rays take only the extinction; emission-only media leave them untouched.
TEST(MediaIntegration, ShadowRaysSeeNoEmission) {
  Media m;
  m.emission = Colour{1, 1, 1, 0, 0};
  const MediaEffect e = integrate(m, 3.0, true);
  EXPECT_EQ(e.emitted, (Vec3{0, 0, 0}));
  EXPECT_EQ(e.transmittance, (Vec3{1, 1, 1}));
}

}  // namespace

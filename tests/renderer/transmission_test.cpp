// Transmission and the recursion limits (povray-pixel-pipeline.md §4): ior-1 continuation without a trace level,
// Heckbert refraction (Snell), total internal reflection, max_trace_level → black, adc_bailout, and the transmit
// (alpha) that travels back through transparent surfaces (§4 "result", §5).
#include <gtest/gtest.h>

#include <cmath>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

BuildOptions with_alpha(bool alpha) {
  BuildOptions o;
  o.output_alpha = alpha;
  return o;
}

constexpr double kPi = 3.14159265358979323846;

Object glass_box(double z, const Colour& pigment, double ior) {
  Object o = box_object({-5, -5, z}, {5, 5, z + 0.1}, texture(pigment, finish_ambient_diffuse(0, 0)));
  o.interior = Interior{};
  o.interior->ior = ior;
  return o;
}

// item4_transmission.pov: `boxes` thin boxes at z = 0, 1, …, white background, max_trace_level 5.
SceneDescription box_stack(int boxes, const Colour& pigment, double ior, int max_trace_level = 5) {
  SceneDescription s = base_scene();
  s.camera = ortho_camera(2, 2);
  s.background = rgb(1, 1, 1);
  s.settings.max_trace_level = max_trace_level;
  for (int k = 0; k < boxes; ++k) s.objects.push_back(glass_box(k, pigment, ior));
  return s;
}

TEST(Transmission, Ior1StackDoesNotConsumeTraceLevels) {
  // [V item4_transmission mode 0] 6 boxes = 12 crossings of rgbt 0.9 with max_trace_level 5: each crossing is a
  // continued ray at the same level, so the white background arrives as 0.9^12 = 0.28243.
  const Radiance r = trace_xy(box_stack(6, rgbft(1, 1, 1, 0, 0.9), 1.0), 0.25, -0.25);
  EXPECT_RGB_REL(r.colour, std::pow(0.9, 12), std::pow(0.9, 12), std::pow(0.9, 12));
  EXPECT_NEAR(r.colour.x, 0.28243, 5e-6);
}

TEST(Transmission, FilterTintsTransmitDoesNot) {
  // [V item4_transmission modes 2/3] rgbf <1,0.5,0.25,0.9>: per crossing S·0.9 → (0.9, 0.45, 0.225)^12;
  // rgbft <1,0.5,0.25,0.5,0.3>: S·0.5 + 0.3 → (0.8, 0.55, 0.425)^12.
  Radiance r = trace_xy(box_stack(6, rgbft(1, 0.5, 0.25, 0.9, 0), 1.0), 0, 0);
  EXPECT_RGB_REL(r.colour, std::pow(0.9, 12), std::pow(0.45, 12), std::pow(0.225, 12));
  r = trace_xy(box_stack(6, rgbft(1, 0.5, 0.25, 0.5, 0.3), 1.0), 0, 0);
  EXPECT_RGB_REL(r.colour, std::pow(0.8, 12), std::pow(0.55, 12), std::pow(0.425, 12));
}

TEST(Transmission, RefractingSurfacesUseUpTraceLevels) {
  // [V item4_transmission mode 1] the same 12 crossings with ior 1.5 each take a level: black.
  EXPECT_EQ(trace_xy(box_stack(6, rgbft(1, 1, 1, 0, 0.9), 1.5), 0, 0).colour, (Vec3{0, 0, 0}));
}

TEST(Transmission, MaxTraceLevelExceededIsBlackNotBackground) {
  // §4: primary ray = level 1, each refraction one deeper; a ray deeper than max_trace_level yields black.
  // 2 boxes = 4 refractions (normal incidence, so the rays stay on the axis): the background ray is level 5.
  const double k = std::pow(0.9, 4);
  EXPECT_RGB_REL(trace_xy(box_stack(2, rgbft(1, 1, 1, 0, 0.9), 1.5, 5), 0, 0).colour, k, k, k);
  const Radiance r = trace_xy(box_stack(2, rgbft(1, 1, 1, 0, 0.9), 1.5, 4), 0, 0);
  EXPECT_EQ(r.colour, (Vec3{0, 0, 0}));
  EXPECT_EQ(r.transmit, 0.0);
  // max_trace_level 1: only the primary ray; the single box's refraction is already too deep.
  EXPECT_EQ(trace_xy(box_stack(1, rgbft(1, 1, 1, 0, 0.9), 1.5, 1), 0, 0).colour, (Vec3{0, 0, 0}));
  // An ior-1 box continues the ray at the same level, but POV-Ray tests that shared level against the maximum
  // before tracing it: with max_trace_level 1 the continued ray is black too, with 2 it shows the background
  // (povray 3.7.0.10, +WT1: an rgbt 0.9 box of ior 1 before a white background renders 0 and 0.810).
  EXPECT_EQ(trace_xy(box_stack(1, rgbft(1, 1, 1, 0, 0.9), 1.0, 1), 0, 0).colour, (Vec3{0, 0, 0}));
  EXPECT_RGB_REL(trace_xy(box_stack(1, rgbft(1, 1, 1, 0, 0.9), 1.0, 2), 0, 0).colour, 0.81, 0.81, 0.81);
}

// Refraction scene (after item4_refraction.pov): glass half-space y < 0 (ior 1.5, rgbf 1 = clear filter); an opaque
// white floor y = −1, diffuse 1, lit by a light at <0,−0.5,0>, so the floor's value N·L = 0.5/√(x² + 0.25) at the hit
// (x, −1, 0) reveals where the refracted ray landed.
SceneDescription refraction_scene() {
  SceneDescription s = base_scene();
  s.background = rgb(0, 0, 1);
  Object glass = plane_object({0, 1, 0}, 0, texture(rgbft(1, 1, 1, 1, 0), finish_ambient_diffuse(0, 0)));
  glass.interior = Interior{};
  glass.interior->ior = 1.5;
  s.objects.push_back(glass);
  s.objects.push_back(plane_object({0, 1, 0}, -1, texture(rgb(1, 1, 1), finish_ambient_diffuse(0, 1))));
  s.lights.push_back(point_light({0, -0.5, 0}));
  return s;
}

TEST(Transmission, RefractionFollowsSnell) {
  // A ray at incidence θi from (0,1,0) hits the glass at (tan θi, 0, 0); Snell: sin θt = sin θi / 1.5; it then
  // travels 1 unit down to the floor at x = tan θi + tan θt.
  const RenderScene rs = build_render_scene(refraction_scene(), BuildOptions{});
  for (double deg : {0.0, 30.0, 45.0, 60.0, 80.0}) {
    const double ti = deg * kPi / 180;
    const double st = std::sin(ti) / 1.5;
    const double x = std::tan(ti) + st / std::sqrt(1 - st * st);
    const Radiance r = trace_at(rs, {0, 1, 0}, {std::sin(ti), -std::cos(ti), 0});
    const double expected = 0.5 / std::sqrt(x * x + 0.25);
    EXPECT_RGB_REL(r.colour, expected, expected, expected) << deg << " degrees";
  }
}

TEST(Transmission, RefractionLeavingTheGlass) {
  // From inside (0,−0.5,0) upward at 30°: η = 1.5, sin θt = 1.5·sin 30° = 0.75. The ray exits at (0.5·tan 30°, 0, 0)
  // and reaches y = 1 at x_hit = x_exit + tan θt. An ambient-1 box only 0.02 wide around x_hit (y ∈ [1, 2]) is seen
  // only along the Snell direction.
  SceneDescription s = refraction_scene();
  const double x_exit = 0.5 * std::tan(30 * kPi / 180);
  const double x_hit = x_exit + 0.75 / std::sqrt(1 - 0.75 * 0.75);   // at y = 1
  s.objects.push_back(box_object({x_hit - 0.01, 1, -1}, {x_hit + 0.01, 2, 1},
                                 texture(rgb(1, 0.5, 0.25), finish_ambient_diffuse(1, 0))));
  const RenderScene rs = build_render_scene(s, BuildOptions{});
  const Vec3 dir{std::sin(30 * kPi / 180), std::cos(30 * kPi / 180), 0};
  EXPECT_RGB_REL(trace_at(rs, {0, -0.5, 0}, dir).colour, 1.0, 0.5, 0.25);
  // Aimed 1° off, the ray misses the 0.02-wide target and shows the (blue) background.
  const Vec3 off{std::sin(31 * kPi / 180), std::cos(31 * kPi / 180), 0};
  EXPECT_RGB_REL(trace_at(rs, {0, -0.5, 0}, off).colour, 0.0, 0.0, 1.0);
}

// TIR scene (after item4_tir.pov): the camera sits inside the glass half-space y < 0 (ior 1.5, red filter) and looks
// up at angle θ from the normal; above is a white background, below an ambient-1 green floor at y = −1.
SceneDescription tir_scene() {
  SceneDescription s = base_scene();
  s.background = rgb(1, 1, 1);
  Object glass = plane_object({0, 1, 0}, 0, texture(rgbft(1, 0, 0, 1, 0), finish_ambient_diffuse(0, 0)));
  glass.interior = Interior{};
  glass.interior->ior = 1.5;
  s.objects.push_back(glass);
  s.objects.push_back(plane_object({0, 1, 0}, -1, texture(rgb(0, 1, 0), finish_ambient_diffuse(1, 0))));
  return s;
}

TEST(Transmission, TotalInternalReflectionThreshold) {
  // Leaving glass η = 1.5: t = 1 + η²(cos²θ − 1) < 0 ⇔ sin θ > 1/1.5, θc = asin(2/3) = 41.81°.
  // Below θc the ray refracts into the white sky through the red filter → (1, 0, 0); above, the mirror ray sees
  // the green floor, not multiplied by the filter (§4 TIR [V item4_tir]) → (0, 1, 0).
  const RenderScene rs = build_render_scene(tir_scene(), BuildOptions{});
  const double tc = std::asin(1 / 1.5);
  auto at = [&](double theta) { return trace_at(rs, {0, -0.5, 0}, {std::sin(theta), std::cos(theta), 0}); };
  EXPECT_RGB_REL(at(tc - 1e-6).colour, 1.0, 0.0, 0.0);
  EXPECT_RGB_REL(at(tc + 1e-6).colour, 0.0, 1.0, 0.0);
  EXPECT_RGB_REL(at(20 * kPi / 180).colour, 1.0, 0.0, 0.0);
  EXPECT_RGB_REL(at(70 * kPi / 180).colour, 0.0, 1.0, 0.0);
  EXPECT_EQ(at(70 * kPi / 180).transmit, 0.0);
}

TEST(Transmission, TotalInternalReflectionUsesATraceLevel) {
  // The mirror ray is one level deeper: with max_trace_level 1 the TIR contribution is black.
  SceneDescription s = tir_scene();
  s.settings.max_trace_level = 1;
  const RenderScene rs = build_render_scene(s, BuildOptions{});
  const Radiance r = trace_at(rs, {0, -0.5, 0}, {std::sin(1.2), std::cos(1.2), 0});
  EXPECT_EQ(r.colour, (Vec3{0, 0, 0}));
}

// Ten ambient-1 rgbt 0.5 planes at z = 0…9 in front of a white background: each contributes S·att = 0.5, weighted
// by the 0.5^k that the planes in front of it let through; the ray behind plane k has weight 0.5^(k+1).
SceneDescription plane_stack(double adc_bailout) {
  SceneDescription s = base_scene();
  s.background = rgb(1, 1, 1);
  s.settings.adc_bailout = adc_bailout;
  for (int k = 0; k < 10; ++k)
    s.objects.push_back(plane_object({0, 0, -1}, -k, texture(rgbft(1, 1, 1, 0, 0.5), finish_ambient_diffuse(1, 0))));
  return s;
}

TEST(Transmission, AdcBailoutCutsLightRays) {
  // adc_bailout 0.1: planes 0–3 are reached (weights 1, 0.5, 0.25, 0.125); the ray behind plane 3 has weight
  // 0.0625 < 0.1 and returns black: 0.5 + 0.25 + 0.125 + 0.0625 = 0.9375.
  EXPECT_REL(trace_xy(plane_stack(0.1), 0, 0).colour.x, 0.9375);
  // Default 1/255 = 0.0039216: 0.5^8 = 0.0039063 is below it, so planes 0–7 count: 1 − 0.5^8.
  EXPECT_REL(trace_xy(plane_stack(1.0 / 255.0), 0, 0).colour.x, 1 - std::pow(0.5, 8));
  // No bailout: all ten planes and the background behind them: Σ 0.5^(k+1) + 0.5^10 = 1.
  EXPECT_REL(trace_xy(plane_stack(0.0), 0, 0).colour.x, 1.0);
}

TEST(Transmission, NothingTracedWhenTransBelowBailout) {
  // §2/§4: trans = min(1, |grey(filCol)|) ≤ adc_bailout stops the layers and no transmitted ray is traced.
  SceneDescription s = base_scene();
  s.background = rgb(1, 1, 1);
  s.objects.push_back(facing_plane(rgbft(1, 1, 1, 0, 0.003), finish_ambient_diffuse(0, 0)));
  EXPECT_EQ(trace_xy(s, 0, 0).colour, (Vec3{0, 0, 0}));
  s.objects[0] = facing_plane(rgbft(1, 1, 1, 0, 0.005), finish_ambient_diffuse(0, 0));
  EXPECT_RGB_REL(trace_xy(s, 0, 0).colour, 0.005, 0.005, 0.005);
}

TEST(Transmission, TransmitTravelsBackThroughTheSurface) {
  // [V item5_background_alpha] rgbt <1,0.5,0.25,0.6> ambient 1 in front of the default background rgbt <0,0,0,1>:
  // colour S·att = (0.4, 0.2, 0.1); with alpha output the pixel transmit is t_behind·trans = 1·0.6 (alpha 0.4).
  SceneDescription s = base_scene();
  s.background = Colour{0, 0, 0, 0, 1};
  s.objects.push_back(facing_plane(rgbft(1, 0.5, 0.25, 0, 0.6), finish_ambient_diffuse(1, 0)));
  const RenderScene alpha = build_render_scene(s, with_alpha(true));
  Radiance r = trace_at(alpha, {0, 0, -10}, {0, 0, 1});
  EXPECT_RGB_REL(r.colour, 0.4, 0.2, 0.1);
  EXPECT_REL(r.transmit, 0.6);
  // Without alpha the background is premultiplied to black and opaque.
  r = trace_at(build_render_scene(s, BuildOptions{}), {0, 0, -10}, {0, 0, 1});
  EXPECT_RGB_REL(r.colour, 0.4, 0.2, 0.1);
  EXPECT_EQ(r.transmit, 0.0);
  // Opaque background rgb <0.2,0.4,0.6>: 0.4 + 0.6·bg = (0.52, 0.44, 0.46), transmit 0.
  s.background = rgb(0.2, 0.4, 0.6);
  r = trace_at(build_render_scene(s, with_alpha(true)), {0, 0, -10}, {0, 0, 1});
  EXPECT_RGB_REL(r.colour, 0.52, 0.44, 0.46);
  EXPECT_EQ(r.transmit, 0.0);
}

// item5_background_alpha.pov mode 2 (background rgbt <0.2,0.4,0.6,0.5>): a miss, and the rgbt <1,0.5,0.25,0.6> ambient-1
// plane in front of the background. Values seen with POV-Ray 3.7.0.10 (EXR, half float), §5.
SceneDescription half_transparent_background(int version, bool with_plane) {
  SceneDescription s = base_scene();
  s.language_version = version;
  s.background = rgbft(0.2, 0.4, 0.6, 0, 0.5);
  if (with_plane) s.objects.push_back(facing_plane(rgbft(1, 0.5, 0.25, 0, 0.6), finish_ambient_diffuse(1, 0)));
  return s;
}

Radiance background_case(int version, bool with_plane, bool alpha) {
  const RenderScene rs = build_render_scene(half_transparent_background(version, with_plane), with_alpha(alpha));
  return trace_at(rs, {0, 0, -10}, {0, 0, 1});
}

TEST(Background, Version37IsPremultipliedWithOrWithoutAlpha) {
  // 3.7 (§5): the miss colour is rgb·(1 − t) = (0.1, 0.2, 0.3) in both modes — POV-Ray +UA writes (0.1, 0.2, 0.3)
  // α 0.5 — and the plane shows 0.4 + 0.6·(0.1, 0.2, 0.3) = (0.46, 0.32, 0.28), α 0.7 (transmit 0.5·0.6).
  for (bool alpha : {false, true}) {
    Radiance r = background_case(370, false, alpha);
    EXPECT_RGB_REL(r.colour, 0.1, 0.2, 0.3) << "alpha " << alpha;
    EXPECT_REL(r.transmit, alpha ? 0.5 : 0.0);
    r = background_case(370, true, alpha);
    EXPECT_RGB_REL(r.colour, 0.46, 0.32, 0.28) << "alpha " << alpha;
    EXPECT_REL(r.transmit, alpha ? 0.3 : 0.0);
  }
}

TEST(Background, LegacyVersionIgnoresBackgroundTransmit) {
  // #version 3.6 (§5 [S], checked with POV-Ray 3.7.0.10): without alpha t is cleared, so the miss is the full
  // (0.2, 0.4, 0.6) and the plane 0.4 + 0.6·bg = (0.52, 0.44, 0.46); with alpha t is set to 1: a miss is (0,0,0)
  // α 0 whatever the colour, the plane (0.4, 0.2, 0.1) α 0.4.
  Radiance r = background_case(360, false, false);
  EXPECT_RGB_REL(r.colour, 0.2, 0.4, 0.6);
  EXPECT_EQ(r.transmit, 0.0);
  r = background_case(360, true, false);
  EXPECT_RGB_REL(r.colour, 0.52, 0.44, 0.46);
  r = background_case(360, false, true);
  EXPECT_RGB_REL(r.colour, 0.0, 0.0, 0.0);
  EXPECT_EQ(r.transmit, 1.0);
  r = background_case(360, true, true);
  EXPECT_RGB_REL(r.colour, 0.4, 0.2, 0.1);
  EXPECT_REL(r.transmit, 0.6);
}

}  // namespace

// Reflection, interior lists and interior fade (povray-pixel-pipeline.md §4) against values computed by hand or
// with an independent formula: Fresnel from the textbook s/p amplitudes, falloff, metallic tint, exponent, the
// trace-level series of two facing mirrors, and fade with each fade_power rule.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

constexpr double kPi = 3.14159265358979323846;

// A black, unlit mirror floor y = 0 under a white sky: what a ray sees on the floor is its reflectivity.
SceneDescription mirror_floor(const Finish& finish, double ior = 1.0, Colour pigment = rgb(0, 0, 0)) {
  SceneDescription s = base_scene();
  s.background = rgb(1, 1, 1);
  Object floor = plane_object({0, 1, 0}, 0, texture(pigment, finish));
  floor.interior = Interior{};
  floor.interior->ior = ior;
  s.objects.push_back(floor);
  return s;
}

Finish reflecting(Colour lo, Colour hi) {
  Finish f = finish_ambient_diffuse(0, 0);
  f.reflection_min = lo;
  f.reflection_max = hi;
  return f;
}

// The colour seen along a ray coming down onto the floor at `degrees` from the normal.
Radiance seen_at_incidence(const SceneDescription& s, double degrees) {
  const double a = degrees * kPi / 180;
  const RenderScene rs = build_render_scene(s, BuildOptions{});
  return trace_at(rs, {-std::tan(a), 1, 0}, {std::sin(a), -std::cos(a), 0});
}

// Unpolarised Fresnel reflectance of a dielectric from the s and p amplitude coefficients (Snell's law).
double textbook_fresnel(double degrees, double n) {
  const double ci = std::cos(degrees * kPi / 180);
  const double si = std::sqrt(1 - ci * ci);
  const double st = si / n;
  const double ct = std::sqrt(1 - st * st);
  const double rs = (ci - n * ct) / (ci + n * ct);
  const double rp = (n * ci - ct) / (n * ci + ct);
  return 0.5 * (rs * rs + rp * rp);
}

TEST(Reflection, ConstantReflectsTheSkyScaled) {
  const Radiance r = seen_at_incidence(mirror_floor(reflecting(rgb(0.5, 0.5, 0.5), rgb(0.5, 0.5, 0.5))), 30);
  EXPECT_RGB_REL(r.colour, 0.5, 0.5, 0.5);
}

TEST(Reflection, ColourReflectionTintsPerChannel) {
  const Radiance r = seen_at_incidence(mirror_floor(reflecting(rgb(0.2, 0.6, 0.9), rgb(0.2, 0.6, 0.9))), 50);
  EXPECT_RGB_REL(r.colour, 0.2, 0.6, 0.9);
}

TEST(Reflection, FalloffBlendsMinAtNormalIncidenceToMaxAtGrazing) {
  // k = (1 − cos θ)^falloff; R = k·max + (1 − k)·min.
  Finish f = reflecting(rgb(0.1, 0.1, 0.1), rgb(0.9, 0.9, 0.9));
  f.reflection_falloff = 2;
  for (double deg : {0.0, 30.0, 60.0, 85.0}) {
    const double k = std::pow(1 - std::cos(deg * kPi / 180), 2);
    const double expected = 0.9 * k + 0.1 * (1 - k);
    const Radiance r = seen_at_incidence(mirror_floor(f), deg);
    EXPECT_NEAR(r.colour.x, expected, 1e-12) << deg;
  }
}

TEST(Reflection, FresnelMatchesTheTextbookReflectance) {
  Finish f = reflecting(rgb(0, 0, 0), rgb(1, 1, 1));
  f.reflection_fresnel = true;
  EXPECT_NEAR(seen_at_incidence(mirror_floor(f, 1.5), 0).colour.x, 0.04, 1e-12);   // ((n−1)/(n+1))²
  for (double deg : {20.0, 45.0, 60.0, 80.0})
    EXPECT_NEAR(seen_at_incidence(mirror_floor(f, 1.5), deg).colour.x, textbook_fresnel(deg, 1.5), 1e-12) << deg;
}

TEST(Reflection, MetallicTintsByThePigmentAtNormalIncidence) {
  // F(0) = 0.014567225/1.12² − 0.011612903 ≈ 0: R ⊙= 1 + m(1 − F)(S − 1), fully the pigment colour for m = 1.
  Finish f = reflecting(rgb(1, 1, 1), rgb(1, 1, 1));
  f.reflection_metallic = 1;
  const double fade = metallic_fade(0);
  const Radiance r = seen_at_incidence(mirror_floor(f, 1.0, rgb(1, 0.5, 0.25)), 0);
  EXPECT_RGB_REL(r.colour, 1.0, 1 + (1 - fade) * -0.5, 1 + (1 - fade) * -0.75);
}

TEST(Reflection, ExponentRaisesTheReflectedColour) {
  // reflection { 0.5 exponent 2 } of a sky of 0.25: 0.5 · 0.25^(1/2) = 0.25.
  Finish f = reflecting(rgb(0.5, 0.5, 0.5), rgb(0.5, 0.5, 0.5));
  f.reflection_exponent = 2;
  SceneDescription s = mirror_floor(f);
  s.background = rgb(0.25, 0.25, 0.25);
  EXPECT_RGB_REL(seen_at_incidence(s, 10).colour, 0.25, 0.25, 0.25);
}

TEST(Reflection, FacingMirrorsStopAtMaxTraceLevelWithBlack) {
  // [V item4_trace_level] white mirrors (reflection 0.9, ambient 0.1): 0.1·Σ_{k<5} 0.9^k = 0.40951 with the
  // default max_trace_level 5 — the background never shows; level 3 gives 0.271.
  auto mirrors = [](int max_level) {
    SceneDescription s = base_scene();
    s.background = rgb(1, 1, 1);
    s.settings.max_trace_level = max_level;
    Finish f = reflecting(rgb(0.9, 0.9, 0.9), rgb(0.9, 0.9, 0.9));
    f.ambient = rgb(0.1, 0.1, 0.1);
    s.objects.push_back(plane_object({0, 0, 1}, 1, texture(rgb(1, 1, 1), f)));
    s.objects.push_back(plane_object({0, 0, 1}, -1, texture(rgb(1, 1, 1), f)));
    return build_render_scene(s, BuildOptions{});
  };
  EXPECT_NEAR(trace_at(mirrors(5), {0, 0, 0}, {0, 0, 1}).colour.x, 0.40951, 1e-12);
  EXPECT_NEAR(trace_at(mirrors(3), {0, 0, 0}, {0, 0, 1}).colour.x, 0.271, 1e-12);
}

// A clear glass slab 0 < z < 2 (ior 1.5, filter 1) in front of a white background, seen head on: what arrives is
// the fade over the 2 units of glass.
Vec3 through_fading_slab(double fade_distance, double fade_power) {
  SceneDescription s = base_scene();
  s.background = rgb(1, 1, 1);
  Object slab = box_object({-5, -5, 0}, {5, 5, 2}, texture(rgbft(1, 1, 1, 1, 0), finish_ambient_diffuse(0, 0)));
  slab.interior = Interior{};
  slab.interior->ior = 1.5;
  slab.interior->fade_distance = fade_distance;
  slab.interior->fade_power = fade_power;
  slab.interior->fade_colour = rgb(0.5, 0.25, 0);
  s.objects.push_back(slab);
  return trace_at(build_render_scene(s, BuildOptions{}), {0, 0, -1}, {0, 0, 1}).colour;
}

TEST(InteriorFade, EachFadePowerRule) {
  // [V item4_interior_fade] thickness 2, fade colour <.5,.25,0>.
  EXPECT_RGB_REL(through_fading_slab(1, 2), 0.6, 0.4, 0.2);   // fc + (1 − fc)/(1 + 2²)
  EXPECT_RGB_REL(through_fading_slab(1, 1000), std::exp(-1.0), std::exp(-1.5), std::exp(-2.0));
  EXPECT_RGB_REL(through_fading_slab(1, 0), 0.75, 0.625, 0.5);   // no fade_power: the constant (1 + fc)/2
  EXPECT_RGB_REL(through_fading_slab(4, 1), 0.5 + 0.5 / 1.5, 0.25 + 0.75 / 1.5, 1 / 1.5);   // (2/4)¹
}

TEST(InteriorList, NestedObjectsRefractRelativeToTheirContainer) {
  // A ray enters glass (1.5) and then water (1.33) inside it at 30°: Snell across the inner surface uses
  // 1.5/1.33, so the direction inside the water is sin θw = sin θg · 1.5/1.33 with sin θg = sin 30° / 1.5.
  SceneDescription s = base_scene();
  s.background = rgb(0, 0, 1);
  auto clear = texture(rgbft(1, 1, 1, 1, 0), finish_ambient_diffuse(0, 0));
  Object glass = plane_object({0, 1, 0}, 0, clear);
  glass.interior = Interior{};
  glass.interior->ior = 1.5;
  Object water = plane_object({0, 1, 0}, -1, clear);
  water.interior = Interior{};
  water.interior->ior = 1.33;
  s.objects.push_back(glass);
  s.objects.push_back(water);
  // A light at the floor y = −3 marks where the ray lands: the floor's N·L reveals the landing x.
  s.objects.push_back(plane_object({0, 1, 0}, -3, texture(rgb(1, 1, 1), finish_ambient_diffuse(0, 1))));
  s.lights.push_back(point_light({0, -2.5, 0}));
  const double si = std::sin(30 * kPi / 180);
  const double sg = si / 1.5, sw = sg * 1.5 / 1.33;
  const double x = std::tan(30 * kPi / 180) + sg / std::sqrt(1 - sg * sg) + 2 * sw / std::sqrt(1 - sw * sw);
  const double expected = 0.5 / std::sqrt(x * x + 0.25);
  const Radiance r = trace_at(build_render_scene(s, BuildOptions{}), {0, 1, 0}, {si, -std::cos(30 * kPi / 180), 0});
  EXPECT_NEAR(r.colour.x, expected, 1e-9);
}

}  // namespace

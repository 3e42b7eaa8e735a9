// POV-Ray 3.7's finish model (povray-pixel-pipeline.md §2) on item2_finish.pov's scene: orthographic camera at
// z = −10 looking along +z (D = +z), the plane z = 0 with N = −z, a light at <3,2,−4> of colour <1,0.9,0.8>,
// pigment <0.8,0.6,0.4>, background <0.2,0.4,0.6>. Every expected value is written out by hand from §2's formulas.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

constexpr double kPi = 3.14159265358979323846;
const Vec3 kLight{3, 2, -4};
const Vec3 kLc{1, 0.9, 0.8};
const Vec3 kS{0.8, 0.6, 0.4};

SceneDescription finish_scene(const Colour& pigment, const Finish& finish, Vec3 light = kLight) {
  SceneDescription s = base_scene();
  s.background = rgb(0.2, 0.4, 0.6);
  s.lights.push_back(point_light(light, rgb(1, 0.9, 0.8)));
  s.objects.push_back(facing_plane(pigment, finish));
  return s;
}

Radiance shade(const Colour& pigment, const Finish& finish, double x, double y, Vec3 light = kLight) {
  return trace_xy(finish_scene(pigment, finish, light), x, y);
}

// N·L at the hit (x, y, 0) for a light at `light`, N = −z.
double n_dot_l(Vec3 light, double x, double y) {
  const Vec3 v = light - Vec3{x, y, 0};
  return -v.z / length(v);
}

// §2's empirical metallic fade, written out independently of the renderer's metallic_fade().
double fade_F(double cos_angle) {
  const double x = std::acos(cos_angle) / (kPi / 2);
  return std::clamp(0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903, 0.0, 1.0);
}

TEST(Finish, DefaultsMatchVerifiedPixel) {
  // [V item2_finish mode 9] finish {} at pixel (3,0) of 4×4: hit (1.5, 1.5, 0); L ∝ (1.5, 0.5, −4), |v| = √18.5,
  // c = 4/√18.5. Colour = S·0.1 (ambient) + 0.6·c·S⊙Lc = (0.52639, 0.36131, 0.21856).
  // The default ambient is the single-precision colour 0.1f, as POV-Ray stores it.
  const double c = 4 / std::sqrt(18.5), ka = static_cast<float>(0.1);
  const Radiance r = shade(rgb(0.8, 0.6, 0.4), Finish{}, 1.5, 1.5);
  EXPECT_RGB_REL(r.colour, 0.8 * ka + 0.6 * c * 0.8 * 1.0, 0.6 * ka + 0.6 * c * 0.6 * 0.9,
                 0.4 * ka + 0.6 * c * 0.4 * 0.8);
  EXPECT_NEAR(r.colour.x, 0.52639, 5e-6);
  EXPECT_NEAR(r.colour.y, 0.36131, 5e-6);
  EXPECT_NEAR(r.colour.z, 0.21856, 5e-6);
  EXPECT_EQ(r.transmit, 0.0);
}

TEST(Finish, DefaultPigmentIsBlack) {
  // §2: default pigment rgb 0 → an untextured lit plane renders 0.
  SceneDescription s = finish_scene(Colour{}, Finish{});
  s.objects[0].texture = std::make_shared<const Texture>(Texture{{TextureLayer{}}, {}, {}, {}});
  EXPECT_RGB_REL(trace_xy(s, 0.5, 0.5).colour, 0.0, 0.0, 0.0);
}

TEST(Finish, AmbientTimesAmbientLightTimesOpacity) {
  // §2: S_rgb·att·(ambient ⊙ ambient_light), att = 1 − f − t = 1 − 0.3 − 0.2 = 0.5. Background black here, so what
  // the surface lets through adds nothing.
  Finish f;
  f.ambient = Colour{0.2, 0.3, 0.4};
  f.diffuse = 0;
  SceneDescription s = finish_scene(rgbft(0.8, 0.6, 0.4, 0.3, 0.2), f);
  s.background = rgb(0, 0, 0);
  s.settings.ambient_light = Colour{0.5, 0.25, 1};
  const Radiance r = trace_xy(s, -1.5, 0.5);
  EXPECT_RGB_REL(r.colour, 0.8 * 0.5 * (0.2 * 0.5), 0.6 * 0.5 * (0.3 * 0.25), 0.4 * 0.5 * (0.4 * 1));
}

TEST(Finish, EmissionIsMultipliedByThePigment) {
  // [V item2_finish mode 6] S ⊙ (ambient ⊙ ambient_light + emission), opaque pigment.
  Finish f;
  f.ambient = Colour{0.2, 0.3, 0.4};
  f.emission = Colour{0.1, 0.2, 0.3};
  f.diffuse = 0;
  SceneDescription s = finish_scene(rgb(0.8, 0.6, 0.4), f);
  s.settings.ambient_light = Colour{0.5, 0.25, 1};
  const Radiance r = trace_xy(s, 0.5, -0.5);
  EXPECT_RGB_REL(r.colour, 0.8 * (0.1 + 0.1), 0.6 * (0.075 + 0.2), 0.4 * (0.4 + 0.3));
}

TEST(Finish, DiffuseWithBrilliance) {
  // [V item2_finish mode 1] ambient 0 diffuse 0.7 brilliance 3 → 0.7·c³·S⊙Lc; at (−0.5, 0.5): v = (3.5, 1.5, −4).
  Finish f = finish_ambient_diffuse(0, 0.7);
  f.brilliance = 3;
  const double c = 4 / std::sqrt(3.5 * 3.5 + 1.5 * 1.5 + 16);
  ASSERT_DOUBLE_EQ(c, n_dot_l(kLight, -0.5, 0.5));
  const Radiance r = shade(rgb(0.8, 0.6, 0.4), f, -0.5, 0.5);
  const double k = 0.7 * c * c * c;
  EXPECT_RGB_REL(r.colour, k * 0.8 * 1.0, k * 0.6 * 0.9, k * 0.4 * 0.8);
}

TEST(Finish, BacksideDiffuseOnlyFromTheSecondValue) {
  // [V item2_finish mode 7] light <1,−1,5> behind the plane; diffuse 0.6, 0.3 → 0.3·|c|·S⊙Lc, no front diffuse.
  // At (0.5, 0.5): v = (0.5, −1.5, 5), c = −5/√27.5.
  const Vec3 behind{1, -1, 5};
  Finish f = finish_ambient_diffuse(0, 0.6);
  f.diffuse_back = 0.3;
  const double c = -5 / std::sqrt(0.25 + 2.25 + 25);
  ASSERT_DOUBLE_EQ(c, n_dot_l(behind, 0.5, 0.5));
  Radiance r = shade(rgb(0.8, 0.6, 0.4), f, 0.5, 0.5, behind);
  EXPECT_RGB_REL(r.colour, 0.3 * -c * 0.8, 0.3 * -c * 0.6 * 0.9, 0.3 * -c * 0.4 * 0.8);

  // Brilliance applies to |c| too; phong and specular give nothing for a light behind the surface.
  f.brilliance = 2;
  f.phong = 1;
  f.specular = 1;
  r = shade(rgb(0.8, 0.6, 0.4), f, 0.5, 0.5, behind);
  EXPECT_RGB_REL(r.colour, 0.3 * c * c * 0.8, 0.3 * c * c * 0.6 * 0.9, 0.3 * c * c * 0.4 * 0.8);
}

TEST(Finish, LightBehindGivesNoHighlightAtAll) {
  // §2: c < 1e-10 and no second diffuse value → the light contributes nothing, not even phong/specular (the Blinn
  // half vector would still be above the surface: N·(V+L) = 1 + c > 0).
  Finish f = finish_ambient_diffuse(0, 0.6);
  f.phong = 1;
  f.phong_size = 1;
  f.specular = 1;
  f.roughness = 1;
  const Radiance r = shade(rgb(0.8, 0.6, 0.4), f, 0.5, 0.5, {1, -1, 0.5});
  EXPECT_EQ(r.colour, (Vec3{0, 0, 0}));
}

TEST(Finish, PhongAtNormalView) {
  // [V item2_finish mode 2] phong 0.8 phong_size 10. Orthographic view: R = D − 2(D·N)N = −z = N, so p = R·L = c.
  Finish f = finish_ambient_diffuse(0, 0);
  f.phong = 0.8;
  f.phong_size = 10;
  const double c = 4 / std::sqrt(18.5);   // hit (1.5, 1.5, 0)
  const Radiance r = shade(rgb(0.8, 0.6, 0.4), f, 1.5, 1.5);
  const double k = 0.8 * std::pow(c, 10);
  // Highlight colour = light colour (not the pigment) without metallic.
  EXPECT_RGB_REL(r.colour, k * 1.0, k * 0.9, k * 0.8);
}

TEST(Finish, PhongOnAnObliqueRay) {
  // D = (1,0,2)/√5 from (−2,0,−4) hits the origin; R = D − 2(D·N)N = (1,0,−2)/√5; L = (3,2,−4)/√29;
  // p = R·L = (3 + 8)/√145. phong 1 phong_size 3 → p³·Lc (diffuse 0, ambient 0).
  Finish f = finish_ambient_diffuse(0, 0);
  f.phong = 1;
  f.phong_size = 3;
  const RenderScene rs = build_render_scene(finish_scene(rgb(0.8, 0.6, 0.4), f), BuildOptions{});
  const Radiance r = trace_at(rs, {-2, 0, -4}, {1, 0, 2});
  const double p = 11 / std::sqrt(145.0);
  const double k = p * p * p;
  EXPECT_RGB_REL(r.colour, k, k * 0.9, k * 0.8);
}

TEST(Finish, PhongCutoffForLargeSizesAndTinyCosines) {
  // §2: the phong term is 0 when phong_size ≥ 60 and p ≤ 0.0008. Light far along the plane: at the origin
  // L = (1000, 0, −0.5)/|…|, p = R·L = 0.5/√(10⁶ + 0.25) ≈ 0.0005 (and N·L = p > 1e-10, so the light is in front).
  Finish f = finish_ambient_diffuse(0, 0);
  f.phong = 1;
  const Vec3 far{1000, 0, -0.5};
  const double p = 0.5 / std::sqrt(1e6 + 0.25);
  ASSERT_LT(p, 0.0008);
  f.phong_size = 60;
  EXPECT_EQ(shade(rgb(0.8, 0.6, 0.4), f, 0, 0, far).colour, (Vec3{0, 0, 0}));
  f.phong_size = 59;   // below the size limit the (tiny) term is kept
  Radiance r = shade(rgb(0.8, 0.6, 0.4), f, 0, 0, far);
  EXPECT_RGB_REL(r.colour, std::pow(p, 59), std::pow(p, 59) * 0.9, std::pow(p, 59) * 0.8);
  EXPECT_GT(r.colour.x, 0.0);
  // Size ≥ 60 with p above the cut-off keeps the term: light at (100, 0, −0.5), p = 0.5/√(10⁴ + 0.25) ≈ 0.005.
  f.phong_size = 60;
  const double p2 = 0.5 / std::sqrt(1e4 + 0.25);
  r = shade(rgb(0.8, 0.6, 0.4), f, 0, 0, {100, 0, -0.5});
  EXPECT_RGB_REL(r.colour, std::pow(p2, 60), std::pow(p2, 60) * 0.9, std::pow(p2, 60) * 0.8);
  EXPECT_GT(r.colour.x, 0.0);
}

TEST(Finish, SpecularExponentIsOneOverRoughness) {
  // [V item2_finish mode 3] specular 0.6 roughness 0.1 → 0.6·h^10·Lc, H = (V + L)/2 with V = −D = N, so
  // h = N·(V+L)/|V+L| = (1 + c)/√(2 + 2c) = √((1 + c)/2).
  Finish f = finish_ambient_diffuse(0, 0);
  f.specular = 0.6;
  f.roughness = 0.1;
  const double c = n_dot_l(kLight, -1.5, -0.5);
  const double h = std::sqrt((1 + c) / 2);
  Radiance r = shade(rgb(0.8, 0.6, 0.4), f, -1.5, -0.5);
  double k = 0.6 * std::pow(h, 10);
  EXPECT_RGB_REL(r.colour, k, k * 0.9, k * 0.8);
  // Default roughness 0.05 → exponent 20.
  f.roughness = 0.05;
  r = shade(rgb(0.8, 0.6, 0.4), f, -1.5, -0.5);
  k = 0.6 * std::pow(h, 20);
  EXPECT_RGB_REL(r.colour, k, k * 0.9, k * 0.8);
}

TEST(Finish, PhongAndSpecularAdd) {
  // Both highlight terms are separate and may be combined (§2 "Versus the classic model").
  Finish f = finish_ambient_diffuse(0, 0.5);
  f.phong = 0.3;
  f.phong_size = 5;
  f.specular = 0.2;
  f.roughness = 0.25;
  const double c = n_dot_l(kLight, 0.5, 1.5);
  const double h = std::sqrt((1 + c) / 2);
  const double k = 0.3 * std::pow(c, 5) + 0.2 * std::pow(h, 4);
  const Radiance r = shade(rgb(0.8, 0.6, 0.4), f, 0.5, 1.5);
  EXPECT_RGB_REL(r.colour, 0.5 * c * 0.8 + k, 0.5 * c * 0.6 * 0.9 + 0.9 * k, 0.5 * c * 0.4 * 0.8 + 0.8 * k);
}

TEST(Finish, MetallicPhongTintedByPigmentWithAngleFade) {
  // [V item2_finish mode 4] phong 0.8 phong_size 10 metallic (= 1): Hc = Lc ⊙ (1 + (1 − F)(S − 1)),
  // F = clamp(0.014567225/(x − 1.12)² − 0.011612903, 0, 1), x = acos(N·L)/(π/2).
  Finish f = finish_ambient_diffuse(0, 0);
  f.phong = 0.8;
  f.phong_size = 10;
  f.metallic = 1;
  const double c = n_dot_l(kLight, -1.5, 1.5);
  const double F = fade_F(c);
  EXPECT_GT(F, 0.0);
  EXPECT_LT(F, 0.1);
  const double k = 0.8 * std::pow(c, 10);
  const Radiance r = shade(rgb(0.8, 0.6, 0.4), f, -1.5, 1.5);
  EXPECT_RGB_REL(r.colour, k * 1.0 * (1 + (1 - F) * (0.8 - 1)), k * 0.9 * (1 + (1 - F) * (0.6 - 1)),
                 k * 0.8 * (1 + (1 - F) * (0.4 - 1)));
}

TEST(Finish, MetallicHalfOnSpecular) {
  // [V item2_finish mode 8] specular 0.6 (roughness 0.05 → exponent 20) metallic 0.5.
  Finish f = finish_ambient_diffuse(0, 0);
  f.specular = 0.6;
  f.metallic = 0.5;
  const double c = n_dot_l(kLight, 1.5, -1.5);
  const double F = fade_F(c);
  const double h = std::sqrt((1 + c) / 2);
  const double k = 0.6 * std::pow(h, 20);
  const Radiance r = shade(rgb(0.8, 0.6, 0.4), f, 1.5, -1.5);
  EXPECT_RGB_REL(r.colour, k * 1.0 * (1 + 0.5 * (1 - F) * (0.8 - 1)), k * 0.9 * (1 + 0.5 * (1 - F) * (0.6 - 1)),
                 k * 0.8 * (1 + 0.5 * (1 - F) * (0.4 - 1)));
}

TEST(Finish, MetallicFadeEndPoints) {
  // F(x) = 0.014567225/(x − 1.12)² − 0.011612903 clamped to [0,1]: F(0) = −4.2e-10 → clamped to exactly 0 (fully
  // tinted at normal incidence); F(1) = 0.99999994 (untinted at grazing); for 1 < x < ~1.24 the formula exceeds 1
  // and clamps to 1.
  EXPECT_EQ(metallic_fade(0.0), 0.0);
  EXPECT_NEAR(metallic_fade(1.0), 1.0, 1e-7);
  EXPECT_REL(metallic_fade(1.0), 0.014567225 / (0.12 * 0.12) - 0.011612903);
  EXPECT_EQ(metallic_fade(1.05), 1.0);
  EXPECT_REL(metallic_fade(0.5), 0.014567225 / (0.62 * 0.62) - 0.011612903);
  // Monotonic on [0, 1].
  for (double x = 0; x < 1.0; x += 0.125) EXPECT_LE(metallic_fade(x), metallic_fade(x + 0.125));
}

TEST(Finish, HighlightsNotScaledByOpacityAndSurfaceLetsBackgroundThrough) {
  // [V item2_finish mode 5] rgbft <0.8,0.6,0.4,0.3,0.2>, ambient 0.2 diffuse 0.7 phong 0.5 (size 40):
  // att = 0.5 scales ambient and diffuse, not the phong term; filCol = S·f + t is applied to the background seen
  // through the (ior 1) plane: bg ⊙ (S·0.3 + 0.2).
  Finish f = finish_ambient_diffuse(0.2, 0.7);
  f.phong = 0.5;
  const double c = n_dot_l(kLight, 0.5, 0.5);
  const double att = 0.5;
  const double ph = 0.5 * std::pow(c, 40);
  const Radiance r = shade(rgbft(0.8, 0.6, 0.4, 0.3, 0.2), f, 0.5, 0.5);
  const Vec3 bg{0.2, 0.4, 0.6};
  Vec3 e;
  for (int i = 0; i < 3; ++i) e[i] = kS[i] * 0.2 * att + 0.7 * att * c * kS[i] * kLc[i] + ph * kLc[i] + bg[i] * (kS[i] * 0.3 + 0.2);
  EXPECT_RGB_REL(r.colour, e.x, e.y, e.z);
  // The pigment's own transparency does not reduce the highlight: same phong term for an opaque pigment.
  Finish only_phong = finish_ambient_diffuse(0, 0);
  only_phong.phong = 0.5;
  SceneDescription s = finish_scene(rgbft(0.8, 0.6, 0.4, 0.3, 0.2), only_phong);
  s.background = rgb(0, 0, 0);
  EXPECT_RGB_REL(trace_xy(s, 0.5, 0.5).colour, ph, ph * 0.9, ph * 0.8);
}

TEST(Finish, OpacityBeforeVersion37) {
  // §2: for #version < 3.7, att = 1 − (f·max(r,g,b) + t) = 1 − (0.3·0.8 + 0.2) = 0.56 (3.7: 1 − 0.3 − 0.2 = 0.5).
  Finish f = finish_ambient_diffuse(1, 0.5);
  SceneDescription s = finish_scene(rgbft(0.8, 0.6, 0.4, 0.3, 0.2), f);
  s.background = rgb(0, 0, 0);
  const double c = n_dot_l(kLight, -0.5, -0.5);
  auto expected = [&](double att) {
    Vec3 e;
    for (int i = 0; i < 3; ++i) e[i] = kS[i] * att * 1.0 + 0.5 * att * c * kS[i] * kLc[i];
    return e;
  };
  Vec3 e = expected(0.5);
  EXPECT_RGB_REL(trace_xy(s, -0.5, -0.5).colour, e.x, e.y, e.z);
  s.language_version = 360;
  e = expected(1 - (0.3 * 0.8 + 0.2));
  EXPECT_RGB_REL(trace_xy(s, -0.5, -0.5).colour, e.x, e.y, e.z);
}

TEST(Finish, TwoLightsAdd) {
  Finish f = finish_ambient_diffuse(0, 1);
  SceneDescription s = finish_scene(rgb(0.8, 0.6, 0.4), f);
  s.lights.push_back(point_light({-2, 0, -1}, rgb(0.5, 0.5, 0.5)));
  const double c1 = n_dot_l(kLight, 0, 0), c2 = n_dot_l({-2, 0, -1}, 0, 0);
  EXPECT_REL(c2, 1 / std::sqrt(5.0));
  EXPECT_RGB_REL(trace_xy(s, 0, 0).colour, 0.8 * (c1 * 1.0 + c2 * 0.5), 0.6 * (c1 * 0.9 + c2 * 0.5),
                 0.4 * (c1 * 0.8 + c2 * 0.5));
}

TEST(Layers, TopLayerFiltersTheOnesBelow) {
  // [V item2_layered] orange <1,0.5,0> with filter 0.5 over blue (both ambient 1 diffuse 0), background green:
  // top: S·att = (0.5, 0.25, 0); filCol = S·f = (0.5, 0.25, 0) kills the blue → (0.5, 0.25, 0).
  // With transmit 0.5 instead: filCol = (0.5, 0.5, 0.5) → blue·0.5 → (0.5, 0.25, 0.5). The opaque bottom layer
  // stops the ray, so the green background never shows.
  for (bool transmit : {false, true}) {
    Texture t;
    TextureLayer blue, orange;
    blue.pigment.colour = rgb(0, 0, 1);
    blue.finish = finish_ambient_diffuse(1, 0);
    orange.pigment.colour = transmit ? rgbft(1, 0.5, 0, 0, 0.5) : rgbft(1, 0.5, 0, 0.5, 0);
    orange.finish = finish_ambient_diffuse(1, 0);
    t.layers = {blue, orange};   // written order: the last one is the top layer
    SceneDescription s = base_scene();
    s.background = rgb(0, 1, 0);
    s.objects.push_back(plane_object({0, 0, -1}, 0, std::make_shared<const Texture>(t)));
    const Radiance r = trace_xy(s, 0, 0);
    if (transmit)
      EXPECT_RGB_REL(r.colour, 0.5, 0.25, 0.5);
    else
      EXPECT_RGB_REL(r.colour, 0.5, 0.25, 0.0);
  }
}

}  // namespace

// crand (POV-Ray's ComputeDiffuseColour): each diffuse term is lowered by crand times a uniform number in [0, 1].
// Over many points of a plane lit head-on with diffuse 0.6 and crand 0.4, the values lie in [0.2, 0.6] with the
// mean 0.4 and the variance 0.4²/12 of that uniform spread; the same point always gets the same value.
TEST(Crand, LowersDiffuseByAUniformSpeckle) {
  SceneDescription s = base_scene();
  Finish f = finish_ambient_diffuse(0, 0.6);
  f.crand = 0.4;
  s.objects.push_back(facing_plane(rgb(1, 1, 1), f));
  s.lights.push_back(point_light({0, 0, -1e6}));
  const RenderScene rs = build_render_scene(s, BuildOptions{});
  const int n = 20000;
  double sum = 0, sum2 = 0, lo = 1, hi = 0;
  for (int i = 0; i < n; ++i) {
    const double x = -1.0 + 2.0 * (i % 200) / 200.0, y = -1.0 + 2.0 * (i / 200) / 100.0;
    const double v = trace_at(rs, {x, y, -10}, {0, 0, 1}).colour.x;
    sum += v;
    sum2 += v * v;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  const double mean = sum / n, variance = sum2 / n - mean * mean;
  EXPECT_NEAR(mean, 0.4, 0.005);
  EXPECT_NEAR(variance, 0.16 / 12, 0.0006);
  EXPECT_GE(lo, 0.2 - 1e-9);
  EXPECT_LE(hi, 0.6 + 1e-9);
  EXPECT_EQ(trace_at(rs, {0.3, 0.1, -10}, {0, 0, 1}).colour.x, trace_at(rs, {0.3, 0.1, -10}, {0, 0, 1}).colour.x);
}

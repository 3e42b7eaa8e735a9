// The seed chapter's direct illumination (shared/seed/illumination-directe.md), ShadingModel::textbook:
//   L = ka·La·S + Σ [ kd(N·L)·Ld⊙S + ks(R·E)^n·Ld⊙((1−p)S + p) + ks'(N·H)^n'·Ld⊙((1−p)S + p) ]
// with R = 2(N·L)N − L, E = −D, H = normalise(E + L), p = 1 − metallic, ks = phong (n = phong_size),
// ks' = specular (n' = 1/roughness); a negative N·L, R·E or N·H drops its term.
// Scene: the plane z = 0 (N = −z), light <3,2,−4> of colour <1,0.9,0.8>, pigment S = <0.8,0.6,0.4>.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

const Vec3 kLight{3, 2, -4};
const Vec3 kLc{1, 0.9, 0.8};
const Vec3 kS{0.8, 0.6, 0.4};
const Vec3 kN{0, 0, -1};

SceneDescription textbook_scene(const Finish& finish, Vec3 light = kLight) {
  SceneDescription s = base_scene();
  s.lights.push_back(point_light(light, rgb(1, 0.9, 0.8)));
  s.objects.push_back(facing_plane(rgb(0.8, 0.6, 0.4), finish));
  return s;
}

// The oblique view used below: D = (1,0,2)/√5 from (−2,0,−4) hits the origin, E = −D.
Radiance oblique(const Finish& finish, Vec3 light = kLight) {
  const RenderScene rs = build_render_scene(textbook_scene(finish, light), BuildOptions{});
  return trace_at(rs, {-2, 0, -4}, {1, 0, 2}, ShadingModel::textbook);
}
const Vec3 kE = Vec3{-1, 0, -2} / std::sqrt(5.0);

TEST(Textbook, Ambient) {
  // ka·La·S with ka = <0.2,0.3,0.4>, La = <0.5,0.25,1>.
  Finish f;
  f.ambient = Colour{0.2, 0.3, 0.4};
  f.diffuse = 0;
  SceneDescription s = textbook_scene(f);
  s.settings.ambient_light = Colour{0.5, 0.25, 1};
  EXPECT_RGB_REL(trace_xy(s, 0.5, 0.5, ShadingModel::textbook).colour, 0.2 * 0.5 * 0.8, 0.3 * 0.25 * 0.6,
                 0.4 * 1 * 0.4);
}

TEST(Textbook, Lambert) {
  // kd(N·L)·Ld⊙S, kd = 0.7, hit (1.5, −0.5, 0): L ∝ (1.5, 2.5, −4), N·L = 4/√24.5.
  const Finish f = finish_ambient_diffuse(0, 0.7);
  const double nl = 4 / std::sqrt(1.5 * 1.5 + 2.5 * 2.5 + 16);
  EXPECT_RGB_REL(trace_xy(textbook_scene(f), 1.5, -0.5, ShadingModel::textbook).colour, 0.7 * nl * 1.0 * 0.8,
                 0.7 * nl * 0.9 * 0.6, 0.7 * nl * 0.8 * 0.4);
  // Brilliance is not part of the textbook model.
  Finish b = f;
  b.brilliance = 3;
  EXPECT_RGB_REL(trace_xy(textbook_scene(b), 1.5, -0.5, ShadingModel::textbook).colour, 0.7 * nl * 1.0 * 0.8,
                 0.7 * nl * 0.9 * 0.6, 0.7 * nl * 0.8 * 0.4);
}

TEST(Textbook, LambertDropsALightBehind) {
  // Light <1,−1,5> behind the plane: N·L < 0 → no diffuse (ambient 0.1·S stays).
  const Finish f = finish_ambient_diffuse(0.1, 0.7);
  EXPECT_RGB_REL(trace_xy(textbook_scene(f, {1, -1, 5}), 0.5, 0.5, ShadingModel::textbook).colour, 0.1 * 0.8,
                 0.1 * 0.6, 0.1 * 0.4);
}

TEST(Textbook, PhongPlasticIsLightColoured) {
  // Oblique view: N·L = 4/√29, R = 2(N·L)N − L = (−3,−2,−4)/√29, R·E = (3 + 8)/√145. ks = 0.5, n = 7, p = 1
  // (metallic 0): ks(R·E)^n·Ld.
  Finish f = finish_ambient_diffuse(0, 0);
  f.phong = 0.5;
  f.phong_size = 7;
  const Vec3 L = normalize(kLight);
  const Vec3 R = kN * (2 * dot(kN, L)) - L;
  EXPECT_REL(dot(R, kE), 11 / std::sqrt(145.0));
  const double k = 0.5 * std::pow(11 / std::sqrt(145.0), 7);
  EXPECT_RGB_REL(oblique(f).colour, k * 1.0, k * 0.9, k * 0.8);
}

TEST(Textbook, BlinnWithHalfVector) {
  // H = normalise(E + L), ks' = 0.4, n' = 1/0.125 = 8.
  Finish f = finish_ambient_diffuse(0, 0);
  f.specular = 0.4;
  f.roughness = 0.125;
  const Vec3 L = normalize(kLight);
  const Vec3 H = normalize(kE + L);
  const double nh = dot(kN, H);
  ASSERT_GT(nh, 0.0);
  const double k = 0.4 * std::pow(nh, 8);
  EXPECT_RGB_REL(oblique(f).colour, k * 1.0, k * 0.9, k * 0.8);
}

TEST(Textbook, MetallicTintsTheHighlightWithTheSurfaceColour) {
  // p = 1 − metallic: metallic 1 → (1−p)S + p = S; metallic 0.25 → 0.25·S + 0.75.
  Finish f = finish_ambient_diffuse(0, 0);
  f.phong = 0.5;
  f.phong_size = 7;
  f.metallic = 1;
  const double k = 0.5 * std::pow(11 / std::sqrt(145.0), 7);
  EXPECT_RGB_REL(oblique(f).colour, k * 1.0 * 0.8, k * 0.9 * 0.6, k * 0.8 * 0.4);
  f.metallic = 0.25;
  EXPECT_RGB_REL(oblique(f).colour, k * 1.0 * (0.25 * 0.8 + 0.75), k * 0.9 * (0.25 * 0.6 + 0.75),
                 k * 0.8 * (0.25 * 0.4 + 0.75));
}

TEST(Textbook, PhongDroppedWhenReflectionPointsAwayFromTheEye) {
  // Light on the viewer's side, grazing: L ∝ (−1, 0, −0.1) (light at (−10, 0, −1)). N·L > 0 but
  // R·E = 2(N·L)(N·E) − L·E = (0.4 − 1.2)/(√5·|(−1,0,−0.1)|) < 0 → the phong term is dropped; diffuse remains.
  Finish f = finish_ambient_diffuse(0, 0.5);
  f.phong = 1;
  f.phong_size = 1;
  const Vec3 L = normalize(Vec3{-10, 0, -1});
  const Vec3 R = kN * (2 * dot(kN, L)) - L;
  ASSERT_LT(dot(R, kE), 0.0);
  const double nl = dot(kN, L);
  EXPECT_RGB_REL(oblique(f, {-10, 0, -1}).colour, 0.5 * nl * 0.8, 0.5 * nl * 0.9 * 0.6, 0.5 * nl * 0.8 * 0.4);
}

TEST(Textbook, FullPlasticSum) {
  // Every term together at pixel-like hit (−1.5, 1.5) with the orthographic view (E = N):
  // ka·S + kd(N·L)Ld⊙S + ks(R·E)^n·Ld + ks'(N·H)^n'·Ld, here R·E = N·L = c and N·H = √((1 + c)/2).
  Finish f = finish_ambient_diffuse(0.1, 0.6);
  f.phong = 0.5;
  f.phong_size = 20;
  f.specular = 0.3;
  f.roughness = 0.1;
  const Vec3 v = kLight - Vec3{-1.5, 1.5, 0};
  const double c = -v.z / length(v);
  const double hl = 0.5 * std::pow(c, 20) + 0.3 * std::pow(std::sqrt((1 + c) / 2), 10);
  Vec3 e;
  for (int i = 0; i < 3; ++i) e[i] = 0.1 * kS[i] + 0.6 * c * kLc[i] * kS[i] + hl * kLc[i];
  EXPECT_RGB_REL(trace_xy(textbook_scene(f), -1.5, 1.5, ShadingModel::textbook).colour, e.x, e.y, e.z);
}

TEST(Textbook, AgreesWithPovrayWhereTheModelsCoincide) {
  // No brilliance, opaque pigment, metallic 0, light in front: POV-Ray's model and the textbook one give the same
  // value (ambient colour · ambient_light · S, kd·c·S⊙Ld, same R·L and N·H).
  Finish f = finish_ambient_diffuse(0.2, 0.7);
  f.phong = 0.4;
  f.phong_size = 12;
  f.specular = 0.2;
  const RenderScene rs = build_render_scene(textbook_scene(f), BuildOptions{});
  const Vec3 a = trace_at(rs, {-2, 0, -4}, {1, 0, 2}, ShadingModel::textbook).colour;
  const Vec3 b = trace_at(rs, {-2, 0, -4}, {1, 0, 2}, ShadingModel::povray).colour;
  EXPECT_RGB_REL(a, b.x, b.y, b.z);
  EXPECT_GT(a.x, 0.2 * 0.8);
}

}  // namespace

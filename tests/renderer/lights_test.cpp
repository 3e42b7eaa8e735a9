// Light sources and shadows (povray-pixel-pipeline.md §3) on item3_lights.pov's scene: orthographic camera at
// z = −10 looking along +z, white plane z = 0 (N = −z) with ambient 0 diffuse 1, so a pixel's value is N·L times
// the light's attenuation (and its shadow filter).
#include <gtest/gtest.h>

#include <cmath>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

constexpr double kPi = 3.14159265358979323846;

SceneDescription lit_plane(const Light& light, Finish finish = finish_ambient_diffuse(0, 1)) {
  SceneDescription s = base_scene();
  s.lights.push_back(light);
  s.objects.push_back(facing_plane(rgb(1, 1, 1), finish));
  return s;
}

double n_dot_l(Vec3 light, Vec3 p) {
  const Vec3 v = light - p;
  return -v.z / length(v);
}

double smoothstep(double a, double b, double x) {
  if (x >= b) return 1;
  if (x <= a) return 0;
  const double s = (x - a) / (b - a);
  return (3 - 2 * s) * s * s;
}

Light spotlight(double radius, double falloff, double tightness) {
  Light l = point_light({0, 0, -4});
  l.spotlight = true;
  l.point_at = {0, 0, 0};
  l.radius = radius;
  l.falloff = falloff;
  l.tightness = tightness;
  return l;
}

// The hit point on z = 0 where the spot's angle from its axis is `degrees` (light at <0,0,−4> aimed at the origin).
double x_at_angle(double degrees) { return 4 * std::tan(degrees * kPi / 180); }

TEST(Lights, PointLightHasNoDistanceFalloff) {
  const Light l = point_light({1, 1, -2}, rgb(1, 0.5, 0.25));
  const Vec3 p{-1, 0.5, 0};
  const double c = n_dot_l(l.location, p);   // v = (2, 0.5, −2) → c = 2/√8.25
  EXPECT_REL(c, 2 / std::sqrt(8.25));
  EXPECT_RGB_REL(trace_xy(lit_plane(l), p.x, p.y).colour, c, 0.5 * c, 0.25 * c);
}

TEST(Lights, FadeDistanceAndPower) {
  // §3 [V item3_lights modes 0 and 6]: A_fade = 2/(1 + (d/fade_distance)^fade_power).
  Light l = point_light({1, 1, -2});
  l.fade_distance = 2;
  l.fade_power = 2;
  const Vec3 p{-1.5, 0.5, 0};
  const double d = std::sqrt(2.5 * 2.5 + 0.5 * 0.5 + 4);
  const double c = 2 / d;
  EXPECT_REL(trace_xy(lit_plane(l), p.x, p.y).colour.x, c * 2 / (1 + (d / 2) * (d / 2)));
  l.fade_distance = 3;
  l.fade_power = 1;
  EXPECT_REL(trace_xy(lit_plane(l), p.x, p.y).colour.x, c * 2 / (1 + d / 3));
  // At d = fade_distance the factor is exactly 1: light at distance 2 straight in front of the hit.
  Light near = point_light({0.5, 0.5, -2});
  near.fade_distance = 2;
  near.fade_power = 3;
  EXPECT_REL(trace_xy(lit_plane(near), 0.5, 0.5).colour.x, 1.0);
  // fade_power 0 means no fade (§3: only if fade_power > 0).
  near.fade_power = 0;
  near.fade_distance = 0.5;
  EXPECT_REL(trace_xy(lit_plane(near), 0.5, 0.5).colour.x, 1.0);
}

TEST(Lights, SpotlightInsideRadiusIsFull) {
  // radius 10° falloff 25° tightness 0: a hit 5° off the axis gets the plain N·L.
  const double x = x_at_angle(5);
  const double c = n_dot_l({0, 0, -4}, {x, 0, 0});
  EXPECT_REL(c, std::cos(5 * kPi / 180));
  EXPECT_REL(trace_xy(lit_plane(spotlight(10, 25, 0)), x, 0).colour.x, c);
}

TEST(Lights, SpotlightFalloffZoneIsSmoothstepInCosine) {
  // 15° off the axis: between radius 10° and falloff 25° → A = smoothstep(cos 25°, cos 10°, cos 15°).
  const double x = x_at_angle(15);
  const double cos_t = std::cos(15 * kPi / 180);
  const double a = smoothstep(std::cos(25 * kPi / 180), std::cos(10 * kPi / 180), cos_t);
  EXPECT_GT(a, 0.1);
  EXPECT_LT(a, 0.9);
  EXPECT_REL(trace_xy(lit_plane(spotlight(10, 25, 0)), 0, x).colour.x, cos_t * a);
}

TEST(Lights, SpotlightAimedAtItselfLightsNothing) {
  // point_at = location: POV-Ray keeps the zero direction, every angle test fails (also for cylinder lights).
  Light spot = spotlight(10, 25, 0);
  spot.point_at = spot.location;
  EXPECT_EQ(trace_xy(lit_plane(spot), 0, 0).colour.x, 0.0);
  spot.cylinder = true;
  EXPECT_EQ(trace_xy(lit_plane(spot), 0, 0).colour.x, 0.0);
}

TEST(Lights, SpotlightOutsideFalloffIsDark) {
  const double x = x_at_angle(30);
  EXPECT_EQ(trace_xy(lit_plane(spotlight(10, 25, 0)), x, 0).colour, (Vec3{0, 0, 0}));
  // Default spotlight (radius 30°, falloff 45°) at 50°: dark; at 20°: full.
  EXPECT_EQ(trace_xy(lit_plane(spotlight(30, 45, 0)), x_at_angle(50), 0).colour, (Vec3{0, 0, 0}));
  EXPECT_REL(trace_xy(lit_plane(spotlight(30, 45, 0)), x_at_angle(20), 0).colour.x, std::cos(20 * kPi / 180));
}

TEST(Lights, SpotlightTightness) {
  // [V item3_lights mode 1] radius 10 falloff 25 tightness 5: A = cosθ⁵ (inside), ·smoothstep (falloff zone).
  const Light l = spotlight(10, 25, 5);
  for (double deg : {0.0, 7.0, 12.0, 20.0}) {
    const double x = x_at_angle(deg);
    const double ct = 4 / std::sqrt(x * x + 16);
    double a = std::pow(ct, 5);
    if (deg > 10) a *= smoothstep(std::cos(25 * kPi / 180), std::cos(10 * kPi / 180), ct);
    EXPECT_REL(trace_xy(lit_plane(l), -x, 0).colour.x, ct * a) << deg << " degrees";
  }
}

TEST(Lights, SpotlightSharpCutWhenFalloffBelowRadius) {
  // §3: falloff < radius → the light is cut off sharply at radius.
  const Light l = spotlight(20, 10, 0);
  EXPECT_REL(trace_xy(lit_plane(l), x_at_angle(19), 0).colour.x, std::cos(19 * kPi / 180));
  EXPECT_EQ(trace_xy(lit_plane(l), x_at_angle(21), 0).colour.x, 0.0);
}

Light parallel_light() {
  // Beam from <−10,0,−10> toward the origin: L = (−1, 0, −1)/√2 everywhere.
  Light l = point_light({-10, 0, -10});
  l.parallel = true;
  l.point_at = {0, 0, 0};
  return l;
}

TEST(Lights, ParallelLightHasAConstantDirection) {
  // [V item3_lights mode 2] N·L = 1/√2 at every hit, whatever its position relative to `location`.
  const SceneDescription s = lit_plane(parallel_light());
  for (double x : {-1.5, 0.0, 1.5}) EXPECT_REL(trace_xy(s, x, 0.5).colour.x, 1 / std::sqrt(2.0));
}

TEST(Lights, ParallelLightShadowDistanceIsTheProjectionOnTheBeam) {
  // [V item3_lights modes 7/8] the shadow test stops at the plane through `location` perpendicular to the beam:
  // from the origin that plane is (location − hit)·L = 20/√2 ≈ 14.1 away. A box around (−5,0,−5) (7.1 along the
  // beam) shadows; a box around (−15,0,−15) (21.2 along the beam, behind the light plane) does not. Both lie
  // outside the orthographic view (x ∈ [−2, 2]).
  SceneDescription s = lit_plane(parallel_light());
  s.objects.push_back(box_object({-6, -1, -6}, {-4, 1, -4}, texture(rgb(1, 1, 1))));
  EXPECT_EQ(trace_xy(s, 0, 0).colour.x, 0.0);
  s.objects[1] = box_object({-16, -1, -16}, {-14, 1, -14}, texture(rgb(1, 1, 1)));
  EXPECT_REL(trace_xy(s, 0, 0).colour.x, 1 / std::sqrt(2.0));
  // A point light at the same place would be shadowed by neither (the far box is behind it) — and by the near one.
  Light point = point_light({-10, 0, -10});
  SceneDescription p = lit_plane(point);
  p.objects.push_back(box_object({-16, -1, -16}, {-14, 1, -14}, texture(rgb(1, 1, 1))));
  EXPECT_REL(trace_xy(p, 0, 0).colour.x, 1 / std::sqrt(2.0));
}

TEST(Lights, ParallelLightFadeUsesTheProjectedDistance) {
  Light l = parallel_light();
  l.fade_distance = 5;
  l.fade_power = 2;
  // Hit (1, 0, 0): d = (location − hit)·L = (11 + 10)/√2.
  const double d = 21 / std::sqrt(2.0);
  EXPECT_REL(trace_xy(lit_plane(l), 1, 0).colour.x, (1 / std::sqrt(2.0)) * 2 / (1 + (d / 5) * (d / 5)));
}

TEST(Lights, ShadowlessLightHasNoShadowAndNoHighlight) {
  // [V item3_lights modes 3/4] phong 1 phong_size 2: a normal light adds p² (R = N, p = c); a shadowless one only
  // gives the diffuse c, even behind an opaque blocker.
  Finish f = finish_ambient_diffuse(0, 1);
  f.phong = 1;
  f.phong_size = 2;
  Light l = point_light({0, 0, -10});
  const Vec3 p{1.5, -0.5, 0};
  const double c = n_dot_l(l.location, p);
  EXPECT_REL(trace_xy(lit_plane(l, f), p.x, p.y).colour.x, c + c * c);
  l.shadowless = true;
  SceneDescription s = lit_plane(l, f);
  EXPECT_REL(trace_xy(s, p.x, p.y).colour.x, c);
  // A shadowless light behind an opaque blocker (a sideways light, so the box stays out of the camera's view)
  // still lights the plane; the same light with shadows is blocked.
  Light side = point_light({-8, 0, -10});
  side.shadowless = true;
  SceneDescription blocked = lit_plane(side, f);
  blocked.objects.push_back(box_object({-7, -8, -6}, {-3.5, 8, -4}, texture(rgb(1, 1, 1))));
  const double cs = n_dot_l(side.location, {0.5, 0.5, 0});
  EXPECT_REL(trace_xy(blocked, 0.5, 0.5).colour.x, cs);
  blocked.lights[0].shadowless = false;
  EXPECT_EQ(trace_xy(blocked, 0.5, 0.5).colour.x, 0.0);
}

// item3_shadow_filter.pov: light <−8,0,−10>; the box <−7,−8,−6>–<−3.5,8,−4> lies outside the view and intercepts
// every shadow ray from the visible plane (each crosses it twice: enters through x = −3.5 or z = −4, leaves
// through z = −6).
SceneDescription shadow_scene() {
  SceneDescription s = lit_plane(point_light({-8, 0, -10}));
  return s;
}
Object occluder(const Colour& pigment) {
  return box_object({-7, -8, -6}, {-3.5, 8, -4}, texture(pigment));
}

TEST(Shadows, OpaqueBlocks) {
  SceneDescription s = shadow_scene();
  const double c = n_dot_l({-8, 0, -10}, {0.5, -1.5, 0});
  EXPECT_REL(trace_xy(s, 0.5, -1.5).colour.x, c);
  s.objects.push_back(occluder(rgb(1, 1, 1)));
  EXPECT_EQ(trace_xy(s, 0.5, -1.5).colour, (Vec3{0, 0, 0}));
}

TEST(Shadows, NoShadowObjectsAreIgnored) {
  SceneDescription s = shadow_scene();
  s.objects.push_back(occluder(rgb(1, 1, 1)));
  s.objects.back().no_shadow = true;
  const double c = n_dot_l({-8, 0, -10}, {-1.5, 1.5, 0});
  EXPECT_REL(trace_xy(s, -1.5, 1.5).colour.x, c);
}

TEST(Shadows, TransparentBoxFiltersAtBothCrossings) {
  // [V item3_shadow_filter mode 1] rgbft <1,0.5,0.25,0.6,0.2>: per crossing S·f + t = (0.8, 0.5, 0.35), twice →
  // (0.64, 0.25, 0.1225) times the unshadowed N·L. ior 1.5 changes nothing (shadow rays do not refract).
  for (double ior : {1.0, 1.5}) {
    SceneDescription s = shadow_scene();
    s.objects.push_back(occluder(rgbft(1, 0.5, 0.25, 0.6, 0.2)));
    s.objects.back().interior = Interior{};
    s.objects.back().interior->ior = ior;
    for (Vec3 p : {Vec3{0.5, 0.5, 0}, Vec3{-1.5, -1.5, 0}, Vec3{1.5, 1.5, 0}}) {
      const double c = n_dot_l({-8, 0, -10}, p);
      EXPECT_RGB_REL(trace_xy(s, p.x, p.y).colour, c * 0.8 * 0.8, c * 0.5 * 0.5, c * 0.35 * 0.35);
    }
  }
}

TEST(Shadows, TwoTransparentBoxesMultiply) {
  // [V item3_shadow_filter mode 6] rgbt .5 box then rgbf <1,0.5,0,1> box (translated 3 toward the light):
  // 0.5² · (1, 0.5, 0)² = (0.25, 0.0625, 0).
  SceneDescription s = shadow_scene();
  s.objects.push_back(occluder(rgbft(1, 1, 1, 0, 0.5)));
  s.objects.push_back(box_object({-7, -8, -9}, {-3.5, 8, -7}, texture(rgbft(1, 0.5, 0, 1, 0))));
  const double c = n_dot_l({-8, 0, -10}, {0.5, 0.5, 0});
  EXPECT_RGB_REL(trace_xy(s, 0.5, 0.5).colour, c * 0.25, c * 0.0625, 0.0);
}

TEST(Shadows, FilterAppliesToHighlightsToo) {
  // [V item3_shadow_filter PH=1] phong-only finish: the highlight is scaled by the same (0.64, 0.25, 0.1225).
  Finish f = finish_ambient_diffuse(0, 0);
  f.phong = 1;
  f.phong_size = 1;
  SceneDescription s = lit_plane(point_light({-8, 0, -10}), f);
  const double c = n_dot_l({-8, 0, -10}, {-1.5, 0.5, 0});   // orthographic view: p = R·L = N·L
  EXPECT_REL(trace_xy(s, -1.5, 0.5).colour.x, c);
  s.objects.push_back(occluder(rgbft(1, 0.5, 0.25, 0.6, 0.2)));
  EXPECT_RGB_REL(trace_xy(s, -1.5, 0.5).colour, c * 0.64, c * 0.25, c * 0.35 * 0.35);
}

TEST(Shadows, OpaqueLayerMakesTheObjectOpaque) {
  // §3: an object is opaque when some layer's pigment has no filter/transmit — a transparent top layer over an
  // opaque one still blocks fully.
  Texture t;
  TextureLayer bottom, top;
  bottom.pigment.colour = rgb(1, 1, 1);
  top.pigment.colour = rgbft(1, 1, 1, 0, 0.9);
  t.layers = {bottom, top};
  SceneDescription s = shadow_scene();
  s.objects.push_back(box_object({-7, -8, -6}, {-3.5, 8, -4}, std::make_shared<const Texture>(t)));
  EXPECT_EQ(trace_xy(s, 0.5, 0.5).colour.x, 0.0);
}

}  // namespace

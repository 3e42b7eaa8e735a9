// Fog (fog.cpp, POV-Ray's ComputeFog) against hand-computed values: constant fog over a known depth, filter and
// transmit, ground fog below its offset behaving as constant fog, fog reaching only rays outside non-hollow objects,
// and turbulence that only ever thins the fog.
#include <gtest/gtest.h>

#include <cmath>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

// An ambient-1 white wall 10 units in front of the ray's origin.
SceneDescription wall_scene() {
  SceneDescription s = base_scene();
  s.objects.push_back(plane_object({0, 0, -1}, -10, texture(rgb(1, 1, 1), finish_ambient_diffuse(1, 0))));
  return s;
}

Vec3 seen(const SceneDescription& s, Vec3 origin = {0, 0, 0}) {
  return trace_at(build_render_scene(s, BuildOptions{}), origin, {0, 0, 1}).colour;
}

TEST(Fog, ConstantFogOverTheDepth) {
  SceneDescription s = wall_scene();
  Fog f;
  f.distance = 5;
  f.colour = rgb(0.2, 0.4, 0.6);
  s.fogs.push_back(f);
  const double a = std::exp(-10.0 / 5.0);
  EXPECT_RGB_REL(seen(s), 0.2 * (1 - a) + a, 0.4 * (1 - a) + a, 0.6 * (1 - a) + a);
}

TEST(Fog, FilterTintsAndTransmitBoundsTheAttenuation) {
  SceneDescription s = wall_scene();
  Fog f;
  f.distance = 1;   // exp(−10) < transmit 0.3: the attenuation is 0.3
  f.colour = rgbft(0.5, 0.25, 1, 0.4, 0.3);
  s.fogs.push_back(f);
  const double a = 0.3;
  auto through = [](double c) { return (1 - 0.4) + 0.4 * c; };
  EXPECT_RGB_REL(seen(s), 0.5 * (1 - a) + a * through(0.5), 0.25 * (1 - a) + a * through(0.25),
                 1 * (1 - a) + a * through(1));
}

TEST(Fog, GroundFogBelowItsOffsetIsConstantFog) {
  SceneDescription s = wall_scene();
  Fog ground;
  ground.type = 2;
  ground.distance = 5;
  ground.offset = 3;   // the ray at y = 0 runs below the offset: density 1
  ground.alt = 1;
  ground.colour = rgb(0.2, 0.4, 0.6);
  s.fogs.push_back(ground);
  const double a = std::exp(-2.0);
  EXPECT_RGB_REL(seen(s), 0.2 * (1 - a) + a, 0.4 * (1 - a) + a, 0.6 * (1 - a) + a);
  // Above the offset it thins out as 1/(1 + h²): at h = 1 all the way, the mean density is 1/2.
  s.fogs[0].offset = -1;
  const double b = std::exp(-10.0 * 0.5 / 5.0);
  EXPECT_NEAR(seen(s).x, 0.2 * (1 - b) + b, 1e-12);
}

TEST(Fog, RaysInsideNonHollowObjectsGetNone) {
  // The ray starts inside a clear sphere: no fog while it is inside (POV-Ray's hollow rays); a hollow sphere lets the
  // fog in.
  for (bool hollow : {false, true}) {
    SceneDescription s = wall_scene();
    Object ball = sphere_object({0, 0, 0}, 20, texture(rgbft(1, 1, 1, 0, 1), finish_ambient_diffuse(0, 0)));
    ball.interior = Interior{};
    ball.interior->hollow = hollow;
    s.objects.push_back(ball);
    s.camera.location = {0, 0, 0};
    s.camera.projection = Projection::perspective;
    Fog f;
    f.distance = 5;
    f.colour = rgb(0, 0, 0);
    s.fogs.push_back(f);
    const double expected = hollow ? std::exp(-2.0) : 1.0;
    EXPECT_NEAR(seen(s).x, expected, 1e-12) << "hollow " << hollow;
  }
}

TEST(Fog, TurbulenceOnlyThinsTheFog) {
  SceneDescription s = wall_scene();
  Fog f;
  f.distance = 5;
  f.colour = rgb(0, 0, 0);
  f.turbulence = Turbulence{{0.5, 0.5, 0.5}};
  s.fogs.push_back(f);
  const double plain = std::exp(-2.0);
  for (double y : {-3.0, -1.0, 0.5, 2.0, 4.0}) {
    const double v = seen(s, {0, y, 0}).x;
    EXPECT_GE(v, plain - 1e-12) << y;
    EXPECT_LE(v, 1.0) << y;
  }
  s.fogs[0].turb_depth = 0;   // no depth: exactly the plain fog
  EXPECT_NEAR(seen(s).x, plain, 1e-12);
}

}  // namespace

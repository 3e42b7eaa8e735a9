// Small helpers for the renderer tests: scene descriptions built in code (no parser), one-ray tracing and a
// relative comparison. The standard test scene is item2_finish.pov's: an orthographic camera at z = −10 looking
// along +z at the plane z = 0 whose normal −z faces the camera, so every N, D, L is easy to write by hand.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>

#include "scene/description.hpp"
#include "renderer/render.hpp"
#include "renderer/render_scene.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render::test {

// |actual − expected| ≤ 1e-9 · max(1e-300, |expected|) (pure relative tolerance; exact zero must be exact).
inline ::testing::AssertionResult near_rel(double actual, double expected, double rel = 1e-9) {
  const double tol = rel * std::max(std::fabs(expected), 1e-300);
  if (std::fabs(actual - expected) <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "actual " << actual << " expected " << expected << " (diff "
                                       << actual - expected << ", tolerance " << tol << ")";
}

#define EXPECT_REL(actual, expected) EXPECT_TRUE(::povtrace::render::test::near_rel((actual), (expected)))
inline ::testing::AssertionResult rgb_near_rel(const Vec3& actual, double ex, double ey, double ez,
                                               double rel = 1e-9) {
  const double expected[3] = {ex, ey, ez};
  const char* names[3] = {"red", "green", "blue"};
  for (int i = 0; i < 3; ++i) {
    const ::testing::AssertionResult r = near_rel(actual[i], expected[i], rel);
    if (!r) return ::testing::AssertionFailure() << names[i] << ": " << r.message();
  }
  return ::testing::AssertionSuccess();
}

#define EXPECT_RGB_REL(actual, ex, ey, ez) \
  EXPECT_TRUE(::povtrace::render::test::rgb_near_rel((actual), (ex), (ey), (ez)))

inline Colour rgb(double r, double g, double b) { return Colour{r, g, b, 0, 0}; }
inline Colour rgbft(double r, double g, double b, double f, double t) { return Colour{r, g, b, f, t}; }

inline Finish finish_ambient_diffuse(double ambient, double diffuse) {
  Finish f;
  f.ambient = Colour{ambient, ambient, ambient};
  f.diffuse = diffuse;
  return f;
}

inline std::shared_ptr<const Texture> texture(const Colour& pigment, const Finish& finish = Finish{}) {
  Texture t;
  TextureLayer layer;
  layer.pigment.colour = pigment;
  layer.finish = finish;
  t.layers.push_back(layer);
  return std::make_shared<const Texture>(t);
}

inline Object plane_object(Vec3 normal, double distance, std::shared_ptr<const Texture> tex) {
  Object o;
  Plane p;
  p.normal = normalize(normal);
  p.distance = distance;
  o.shape = p;
  o.texture = std::move(tex);
  return o;
}

inline Object box_object(Vec3 lo, Vec3 hi, std::shared_ptr<const Texture> tex) {
  Object o;
  o.shape = Box{lo, hi};
  o.texture = std::move(tex);
  return o;
}

inline Object sphere_object(Vec3 centre, double radius, std::shared_ptr<const Texture> tex) {
  Object o;
  Sphere s;
  s.centre = centre;
  s.radius = radius;
  o.shape = s;
  o.texture = std::move(tex);
  return o;
}

inline Light point_light(Vec3 location, Colour colour = rgb(1, 1, 1)) {
  Light l;
  l.location = location;
  l.colour = colour;
  return l;
}

// Orthographic camera at <cx,cy,−10> looking along +z, right x*w, up y*h (final vectors, as the parser would
// resolve `orthographic location <cx,cy,-10> look_at <cx,cy,0> right x*w up y*h`).
inline Camera ortho_camera(double w = 4, double h = 4, double cx = 0, double cy = 0) {
  Camera c;
  c.projection = Projection::orthographic;
  c.location = {cx, cy, -10};
  c.direction = {0, 0, 1};
  c.up = {0, h, 0};
  c.right = {w, 0, 0};
  return c;
}

// A #version 3.7 scene with assumed_gamma 1 (working values = linear values), black opaque background.
inline SceneDescription base_scene() {
  SceneDescription s;
  s.language_version = 370;
  s.version_given = true;
  s.settings.assumed_gamma = 1.0;
  s.camera = ortho_camera();
  s.background = Colour{0, 0, 0, 0, 0};
  return s;
}

// The plane z = 0 with its normal −z toward the camera (pipeline item2_finish.pov).
inline Object facing_plane(const Colour& pigment, const Finish& finish) {
  return plane_object({0, 0, -1}, 0, texture(pigment, finish));
}

// Traces one camera ray: the orthographic ray straight down +z through world point (x, y) (origin z = −10).
inline Radiance trace_at(const RenderScene& rs, Vec3 origin, Vec3 direction,
                         ShadingModel model = ShadingModel::povray) {
  Tracer tracer(rs, model);
  return tracer.trace_camera_ray(Ray{origin, normalize(direction)});
}

inline Radiance trace_xy(const SceneDescription& scene, double x, double y,
                         ShadingModel model = ShadingModel::povray) {
  const RenderScene rs = build_render_scene(scene, BuildOptions{});
  return trace_at(rs, {x, y, -10}, {0, 0, 1}, model);
}

}  // namespace povtrace::render::test

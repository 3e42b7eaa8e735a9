// The radiosity evaluator (renderer/radiosity/gather.*) through the renderer (issue 19 step 6,
// docs/issue19-study.md §9.3): scenes whose radiosity value follows from the direction pool alone, with the
// expected values computed here from the pool (the "small script"), and the quality rule (+Q8 renders as if there
// were no radiosity block).
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "parser/parse_scene.hpp"
#include "renderer/radiosity/directions.hpp"
#include "renderer/render.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;

SceneDescription parsed(const std::string& text) {
  ParseOptions o;
  o.message_sink = [](const std::string&) {};
  return parse_scene_text(text, "gather.pov", o);
}

image::Image rendered(const std::string& text, int quality = 9, int threads = 1, int width = 16, int height = 12) {
  BuildOptions b;
  b.quality = quality;
  const RenderScene scene = build_render_scene(parsed(text), b);
  RenderSettings s;
  s.width = width;
  s.height = height;
  s.threads = threads;
  s.quality = quality;
  s.block_size = 8;
  return render::render(scene, s).image;
}

// The study's §5.3 scene: a white diffuse-1 plane seen from above, no lights, a sky whose colour is `sky` in every
// direction, count C = M = 1600 so that every new sample shoots the whole pool once, recursion_limit 1.
std::string sky_scene(const std::string& sky, const std::string& radiosity_extra = "",
                      const std::string& version = "3.7", const std::string& more = "") {
  return "#version " + version + ";\n"
         "global_settings { assumed_gamma 1 radiosity { count 1600, 1600 recursion_limit 1 " + radiosity_extra +
         " } }\n"
         "camera { orthographic location <0, 10, 0> look_at 0 right x * 4 up z * 3 }\n"
         "sky_sphere { pigment { " + sky + " } }\n"
         "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n" + more;
}

const std::string grey_y = "gradient y color_map { [0 rgb 0] [1 rgb 1] }";

// Mean over the 1600-entry Halton pool of f(direction).
Vec3 pool_mean(const std::function<Vec3(Vec3)>& f, std::size_t first = 0, std::size_t end = 1600) {
  const radiosity::DirectionPool pool(1600);
  Vec3 sum;
  for (std::size_t k = first; k < end; ++k) sum += f(pool[k]);
  return sum / static_cast<double>(end - first);
}

void expect_every_pixel(const image::Image& img, Vec3 expected, double tolerance = 1e-6) {
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x) {
      const float* p = img.pixel(x, y);
      ASSERT_NEAR(p[0], expected.x, tolerance) << x << "," << y;
      ASSERT_NEAR(p[1], expected.y, tolerance) << x << "," << y;
      ASSERT_NEAR(p[2], expected.z, tolerance) << x << "," << y;
    }
}

Vec3 all(double v) { return {v, v, v}; }

TEST(GatherRender, SkyFunctionalsAreTheirPoolMeans) {
  // Study §5.3: POV-Ray renders 0.66748, 0.24939, 0.20068 (half-float EXR) where the Halton pool gives
  // 0.66737, 0.24935, 0.20070.
  const Vec3 y = pool_mean([](Vec3 d) { return all(d.y); });
  EXPECT_NEAR(y.x, 0.66737, 5e-6);
  expect_every_pixel(rendered(sky_scene(grey_y)), y);
  const Vec3 x2 = pool_mean([](Vec3 d) { return all(d.x * d.x); });
  EXPECT_NEAR(x2.x, 0.24935, 5e-6);
  expect_every_pixel(rendered(sky_scene("function { x * x } color_map { [0 rgb 0] [1 rgb 1] }")), x2);
  const Vec3 y8 = pool_mean([](Vec3 d) { return all(std::pow(d.y, 8)); });
  EXPECT_NEAR(y8.x, 0.20070, 5e-6);
  expect_every_pixel(rendered(sky_scene("function { pow(y, 8) } color_map { [0 rgb 0] [1 rgb 1] }")), y8);
}

TEST(GatherRender, BelowQuality9TheSceneRendersWithoutRadiosity) {
  // POV-Ray 3.7.0.10 at +Q8: the sky scene is black (ambient 0, no lights), and any scene renders exactly as
  // without its radiosity block (ambient back on).
  expect_every_pixel(rendered(sky_scene(grey_y), 8), all(0), 0);
  const std::string lit = "#version 3.7;\nglobal_settings { assumed_gamma 1 ambient_light 0.5 radiosity { } }\n"
                          "camera { orthographic location <0, 10, 0> look_at 0 right x * 4 up z * 3 }\n"
                          "plane { y, 0 pigment { rgb 1 } finish { ambient 0.4 diffuse 1 } }\n";
  expect_every_pixel(rendered(lit, 8), all(0.2));
  BuildOptions b;
  b.quality = 8;
  EXPECT_NO_THROW((void)build_render_scene(parsed(lit), b));
  b.quality = 9;
  EXPECT_TRUE(build_render_scene(parsed(lit), b).radiosity);
}

TEST(GatherRender, AmbientIsDroppedIn37ScenesAndKeptInOlderOnes) {
  const std::string plane = "plane { y, 0 pigment { rgb 1 } finish { ambient 0.25 diffuse 1 } }\n";
  const Vec3 y = pool_mean([](Vec3 d) { return all(d.y); });
  // The first plane of sky_scene is replaced: ambient 0.25 instead of 0.
  auto with_ambient = [&](const std::string& version) {
    std::string s = sky_scene(grey_y, "", version);
    const std::string old = "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    s.replace(s.find(old), old.size(), plane);
    return s;
  };
  expect_every_pixel(rendered(with_ambient("3.7")), y);
  expect_every_pixel(rendered(with_ambient("3.6")), y + all(0.25));
}

TEST(GatherRender, EmissionOnlyUnderADisc) {
  // An emissive disc of radius 1 at height 1 above the point, seen by no camera ray: A = the share of pool
  // directions that hit it (exact), close to the analytic cosine-weighted share R²/(R² + h²) = ½.
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 1600 recursion_limit 1 } }\n"
      "camera { orthographic location <0, 10, 0> look_at 0 right x * 0.01 up z * 0.01 }\n"
      "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
      "disc { <0, 1, 0>, y, 1 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } no_image }\n";
  const Vec3 share = pool_mean([](Vec3 d) {
    const double t = 1.0 / d.y;
    return all(t * std::sqrt(d.x * d.x + d.z * d.z) < 1.0 ? 1.0 : 0.0);
  });
  EXPECT_NEAR(share.x, 0.5, 5e-3);
  expect_every_pixel(rendered(scene, 9, 1, 1, 1), share);
}

TEST(GatherRender, ImportanceKeepsTheFirstShareOfTheRays) {
  // A miss has the default importance 0.25: rays i with i/1599 > 0.25 are dropped, the 400 kept ones are
  // weighted 1600/400 each, so A is the mean over the first 400 directions.
  const Vec3 y400 = pool_mean([](Vec3 d) { return all(d.y); }, 0, 400);
  expect_every_pixel(rendered("#default { radiosity { importance 0.25 } }\n" + sky_scene(grey_y)), y400);
}

TEST(GatherRender, ACsgChildHasItsOwnImportance) {
  // The emissive disc of EmissionOnlyUnderADisc as a union child with importance 0.25 (the union hidden from the
  // camera): rays i > 399 that hit it are dropped, the kept hits weigh 1600/400 = 4, misses (black sky, default
  // importance 1) weigh 1, so A = 4·hits₄₀₀ / (4·hits₄₀₀ + misses).
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 1600 recursion_limit 1 } }\n"
      "camera { orthographic location <0, 10, 0> look_at 0 right x * 0.01 up z * 0.01 }\n"
      "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
      "union { disc { <0, 1, 0>, y, 1 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } "
      "radiosity { importance 0.25 } } sphere { <0, -50, 0>, 1 } no_image }\n";
  const radiosity::DirectionPool pool(1600);
  double hits = 0, misses = 0;
  for (std::size_t k = 0; k < 1600; ++k) {
    const Vec3 d = pool[k];
    const bool hit = std::sqrt(d.x * d.x + d.z * d.z) / d.y < 1.0;
    if (hit && k < 400) hits += 1;
    if (!hit) misses += 1;
  }
  expect_every_pixel(rendered(scene, 9, 1, 1, 1), all(4 * hits / (4 * hits + misses)));
}

TEST(GatherRender, MaxSampleClampsEachRay) {
  const Vec3 clamped = pool_mean([](Vec3 d) { return all(std::min(d.y, 0.5)); });
  expect_every_pixel(rendered(sky_scene(grey_y, "max_sample 0.5")), clamped);
}

TEST(GatherRender, GrayThresholdAndBrightnessShapeTheReturnedValue) {
  const std::string tinted = "gradient y color_map { [0 rgb 0] [1 rgb <1, 0.5, 0.25>] }";
  const Vec3 a = pool_mean([](Vec3 d) { return Vec3{d.y, 0.5 * d.y, 0.25 * d.y}; });
  const double g = 0.6;
  const double grey = 0.297 * a.x + 0.589 * a.y + 0.114 * a.z;
  expect_every_pixel(rendered(sky_scene(tinted, "gray_threshold 0.6")), a * (1 - g) + all(g * grey));
  expect_every_pixel(rendered(sky_scene(tinted, "brightness 2")), a * 2.0, 2e-6);
}

TEST(GatherRender, NoRadiosityObjectsAreInvisibleToSampleRaysOnly) {
  // A black plane above the white one, hidden from the camera by no_image: it shadows the whole sky from the
  // sample rays unless it is no_radiosity.
  const std::string cover = "plane { y, 0.5 pigment { rgb 0 } finish { ambient 0 diffuse 0 } no_image ";
  expect_every_pixel(rendered(sky_scene(grey_y, "", "3.7", cover + "}\n")), all(0), 0);
  expect_every_pixel(rendered(sky_scene(grey_y, "", "3.7", cover + "no_radiosity }\n")),
                     pool_mean([](Vec3 d) { return all(d.y); }));
}

TEST(GatherRender, SampleRaysSeeNoHighlights) {
  // A sphere seen only by sample rays (no_image), lit by a light: its phong and specular change nothing in the
  // radiosity of the plane below (POV-Ray skips highlights for radiosity rays), its diffuse does.
  auto scene = [](const std::string& finish) {
    return "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 200 recursion_limit 1 } }\n"
           "camera { orthographic location <0, 10, 0> look_at 0 right x * 4 up z * 3 }\n"
           "light_source { <1.5, 0.2, 0> rgb 1 }\n"
           "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
           "sphere { <0, 1.5, 0>, 0.5 pigment { rgb 0.5 } finish { ambient 0 " + finish + " } no_image }\n";
  };
  const image::Image plain = rendered(scene("diffuse 0.6"));
  EXPECT_EQ(rendered(scene("diffuse 0.6 phong 1 phong_size 1 specular 1 roughness 1")).rgba, plain.rgba);
  EXPECT_NE(rendered(scene("diffuse 0.9")).rgba, plain.rgba);
}

TEST(GatherRender, TheImageDoesNotDependOnTheThreadCount) {
  // Few rays per sample, so each sample's directions depend on the block's cursor; a light, a sphere and a second
  // bounce, so that reuse and recursion happen.
  const std::string scene =
      "#version 3.7;\nglobal_settings { assumed_gamma 1 radiosity { count 20 recursion_limit 2 } }\n"
      "camera { location <0, 2, -4> look_at <0, 0.5, 0> }\n"
      "light_source { <3, 5, -2> rgb 1 }\n"
      "sky_sphere { pigment { gradient y color_map { [0 rgb 0] [1 rgb <0.2, 0.4, 1>] } } }\n"
      "plane { y, 0 pigment { checker rgb 1 rgb 0.5 } finish { diffuse 0.7 } }\n"
      "sphere { <0, 1, 0>, 1 pigment { rgb <1, 0.3, 0.2> } finish { phong 1 } }\n";
  const image::Image one = rendered(scene, 9, 1, 32, 24);
  const image::Image three = rendered(scene, 9, 3, 32, 24);
  EXPECT_EQ(one.rgba, three.rgba);
  double sum = 0;
  for (const float v : one.rgba) sum += v;
  EXPECT_GT(sum, 0);
}

}  // namespace

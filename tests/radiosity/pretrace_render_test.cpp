// The pretrace through the renderer (renderer/pretrace_run.*, docs/issue19-study.md §9.3 steps 7–8): radiosity
// images are bit-identical for any thread count (the default parallel order and POV-Ray's one-thread order),
// a region's pixels are the full render's, and the block stop rule stops blocks that see no radiosity surface after
// their first pass.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "parser/parse_scene.hpp"
#include "renderer/pretrace_run.hpp"
#include "renderer/radiosity/pretrace.hpp"
#include "renderer/render.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;

RenderScene built(const std::string& text) {
  ParseOptions o;
  o.message_sink = [](const std::string&) {};
  return build_render_scene(parse_scene_text(text, "pretrace.pov", o), BuildOptions{});
}

// A small Cornell-like box: coloured walls, a light, two boxes; two bounces, few rays, so it stays fast; a coarse
// pretrace and a small error bound, so that the final pass gathers too.
const std::string box_scene =
    "#version 3.7;\n"
    "global_settings { assumed_gamma 1 radiosity { count 24 recursion_limit 2 nearest_count 3 error_bound 0.6 pretrace_start 0.25 pretrace_end 0.25 } }\n"
    "camera { location <0, 1, -0.95> look_at <0, 1, 0> angle 90 }\n"
    "light_source { <0, 1.9, -0.5>, rgb 1 }\n"
    "#declare W = finish { ambient 0 diffuse 0.8 }\n"
    "box { <-1, 0, -1>, <1, 2, 1> inverse pigment { rgb 0.8 } finish { W } }\n"
    "plane { x, -0.999 pigment { rgb <0.8, 0.1, 0.1> } finish { W } }\n"
    "plane { -x, -0.999 pigment { rgb <0.1, 0.8, 0.1> } finish { W } }\n"
    "box { <-0.6, 0, -0.2>, <-0.1, 0.9, 0.3> rotate y * 20 pigment { rgb 0.9 } finish { W } }\n"
    "sphere { <0.45, 0.35, -0.3>, 0.35 pigment { rgb <0.9, 0.9, 0.3> } finish { W } }\n";

image::Image render_with(const RenderScene& scene, int threads, bool povray_order = false, int block = 16,
                         std::optional<image::PixelRect> region = {}) {
  RenderSettings s;
  s.width = 48;
  s.height = 36;
  s.threads = threads;
  s.block_size = block;
  s.radiosity_povray_order = povray_order;
  s.region = region;
  return render::render(scene, s).image;
}

bool same_pixels(const image::Image& a, const image::Image& b) {
  return a.width == b.width && a.height == b.height && a.rgba.size() == b.rgba.size() &&
         std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0;
}

TEST(PretraceRender, TheImageIsTheSameForAnyThreadCount) {
  const RenderScene scene = built(box_scene);
  for (const int block : {8, 16}) {
    const image::Image one = render_with(scene, 1, false, block);
    for (const int threads : {2, 3, 4}) EXPECT_TRUE(same_pixels(one, render_with(scene, threads, false, block)))
        << threads << " threads, block size " << block;
    EXPECT_TRUE(same_pixels(one, render_with(scene, 1, false, block))) << "run to run";
  }
}

TEST(PretraceRender, PovRaysOrderIsTheSameForAnyThreadCountAndDiffersFromTheParallelOrder) {
  const RenderScene scene = built(box_scene);
  const image::Image one = render_with(scene, 1, true);
  EXPECT_TRUE(same_pixels(one, render_with(scene, 4, true)));
  // Not the same order: the default keeps final-pass samples to their block, each block starting its cursors anew.
  EXPECT_FALSE(same_pixels(one, render_with(scene, 1, false)));
}

TEST(PretraceRender, ARegionHasTheFullRendersPixels) {
  const RenderScene scene = built(box_scene);
  const image::Image full = render_with(scene, 2);
  const image::PixelRect r{13, 7, 40, 30};
  const image::Image part = render_with(scene, 2, false, 16, r);
  for (int y = r.y0; y <= r.y1; ++y)
    for (int x = r.x0; x <= r.x1; ++x)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(part.pixel(x, y)[c], full.pixel(x, y)[c]) << x << "," << y;
}

// The pretrace points of every block in pass `pass` (0-based), for a fresh block state.
std::uint64_t points_in_pass(int width, int height, int block, double size) {
  std::uint64_t n = 0;
  radiosity::PretraceJitter j;
  for (int y0 = 0; y0 < height; y0 += block)
    for (int x0 = 0; x0 < width; x0 += block)
      n += radiosity::pretrace_points({x0, y0, std::min(x0 + block, width) - 1, std::min(y0 + block, height) - 1},
                                      radiosity::PretraceBlockState{}, {}, size, j)
               .size();
  return n;
}

TEST(PretraceRender, BlocksThatSeeNoRadiositySurfaceStopAfterTheFirstPass) {
  // 64×64, blocks of 32: passes of 5.12 and 2.56 pixels, 36 or more points per block in the first pass (≥ 9).
  const std::string sky_only =
      "#version 3.7;\nglobal_settings { radiosity { count 10 } }\ncamera { location 0 look_at z }\n"
      "sky_sphere { pigment { rgb 1 } }\nsphere { -10 * z, 1 pigment { rgb 1 } }\n";
  const std::string plane_only =
      "#version 3.7;\nglobal_settings { radiosity { count 10 } }\ncamera { location y look_at <0, 0, 1> }\n"
      "sky_sphere { pigment { rgb 1 } }\nplane { y, 0 pigment { rgb 1 } }\nplane { -y, -2 pigment { rgb 1 } }\n";
  RenderSettings s;
  s.width = s.height = 64;
  s.threads = 2;
  const std::uint64_t first = points_in_pass(64, 64, 32, 5.12), second = points_in_pass(64, 64, 32, 2.56);
  EXPECT_EQ(first, 13u * 13u);   // 7 + 6 grid points across: 0 … 30.72 and 35.84 … 61.44
  const PretraceResult sky = run_pretrace(built(sky_only), s);
  EXPECT_EQ(sky.rays.camera, first);
  EXPECT_TRUE(sky.cache.empty());
  const PretraceResult planes = run_pretrace(built(plane_only), s);
  EXPECT_EQ(planes.rays.camera, first + second);
  EXPECT_FALSE(planes.cache.empty());
}

}  // namespace

// Anti-aliasing (povray-pixel-pipeline.md §7): render() with antialias on and jitter off, compared pixel by pixel
// with a direct C++ transcription of shared/docs/semantics-scenes/item7_aa_check.py's method1/method2 (32-px
// blocks with their traced frame row/column, supersampling each pixel at most once; recursive corner subdivision)
// applied to the analytic shade function of the same scene. Plus the [V] values of item7_aa_edge, thread-count
// independence and deterministic jitter.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "scene_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::render::test;

// ---- Transcription of item7_aa_check.py (jitter 0, working gamma 1, grey samples) --------------------------------
using Shade = std::function<double(double, double)>;
using Pixels = std::map<std::pair<int, int>, double>;

double aa_encode(double v, double gamma = 2.5) { return std::pow(std::max(v, 0.0), 1.0 / gamma); }
double dist(double a, double b) { return 3 * std::fabs(aa_encode(a) - aa_encode(b)); }   // R = G = B, T = 0

Pixels method1(int W, int H, const Shade& shade, int depth = 3, double thr = 0.3, int block = 32) {
  const double step = 1.0 / depth, rng = 0.5 - step * 0.5;
  auto supersample = [&](double px, double py, double c) {
    double col = c;
    double yy = -rng;
    while (yy <= rng + 1e-10) {
      double xx = -rng;
      while (xx <= rng + 1e-10) {
        col += shade(px + xx, py + yy);
        xx += step;
      }
      yy += step;
    }
    return col / (depth * depth + 1);
  };
  Pixels img;
  for (int by = 0; by < H; by += block)
    for (int bx = 0; bx < W; bx += block) {
      const int L = bx, T = by, R = std::min(bx + block, W) - 1, B = std::min(by + block, H) - 1;
      Pixels pix;
      std::map<std::pair<int, int>, bool> done;
      for (int x = L; x <= R; ++x) {
        pix[{x, T - 1}] = shade(x, T - 1);
        done[{x, T - 1}] = true;
      }
      for (int y = T; y <= B; ++y) {
        pix[{L - 1, y}] = shade(L - 1, y);
        done[{L - 1, y}] = true;
        for (int x = L; x <= R; ++x) {
          pix[{x, y}] = shade(x, y);
          const bool ld = dist(pix[{x - 1, y}], pix[{x, y}]) >= thr;
          const bool td = dist(pix[{x, y - 1}], pix[{x, y}]) >= thr;
          if (ld && !done[{x - 1, y}]) {
            pix[{x - 1, y}] = supersample(x - 1.0, y, pix[{x - 1, y}]);
            done[{x - 1, y}] = true;
          }
          if (td && !done[{x, y - 1}]) {
            pix[{x, y - 1}] = supersample(x, y - 1.0, pix[{x, y - 1}]);
            done[{x, y - 1}] = true;
          }
          if (ld || td) {
            pix[{x, y}] = supersample(x, y, pix[{x, y}]);
            done[{x, y}] = true;
          }
        }
      }
      for (int y = T; y <= B; ++y)
        for (int x = L; x <= R; ++x) img[{x, y}] = pix[{x, y}];
    }
  return img;
}

Pixels method2(int W, int H, const Shade& shade, int depth = 3, double thr = 0.3) {
  std::function<double(double, double, double, double, double, double, double, int)> sub =
      [&](double x, double y, double d, double c00, double c01, double c10, double c11, int level) -> double {
    const double cs[4] = {c00, c01, c10, c11};
    bool differ = false;
    if (level > 0)
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j) differ = differ || dist(cs[i], cs[j]) >= thr;
    if (differ) {
      const double l = shade(x - d, y), t = shade(x, y - d), r = shade(x + d, y), b = shade(x, y + d),
                   m = shade(x, y);
      const double h = d / 2;
      return (sub(x - h, y - h, h, c00, l, t, m, level - 1) + sub(x - h, y + h, h, l, c01, m, b, level - 1) +
              sub(x + h, y - h, h, t, m, c10, r, level - 1) + sub(x + h, y + h, h, m, b, r, c11, level - 1)) /
             4;
    }
    return (c00 + c01 + c10 + c11) / 4;
  };
  Pixels img;
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x)
      img[{x, y}] = sub(x, y, 0.5, shade(x - .5, y - .5), shade(x - .5, y + .5), shade(x + .5, y - .5),
                        shade(x + .5, y + .5), depth - 1);
  return img;
}

// ---- Scenes ------------------------------------------------------------------------------------------------------
// item7_aa_blocks.pov in pixel coordinates: X = sx + 0.5, Y = −(sy + 0.5); white where X + 0.7Y < 13.0123, a grey
// 0.5 disc of radius 7.3123 around (30.017, −30.011) in front, black elsewhere.
double shade_blocks(double sx, double sy) {
  const double X = sx + 0.5, Y = -(sy + 0.5);
  if ((X - 30.017) * (X - 30.017) + (Y + 30.011) * (Y + 30.011) < 7.3123 * 7.3123) return 0.5;
  return X + 0.7 * Y < 13.0123 ? 1.0 : 0.0;
}

// The same picture from povtrace primitives: orthographic camera over x ∈ [0,40], y ∈ [−40,0]; the white half-plane is
// a box whose x = 0 face is turned onto the line X + 0.7Y = 13.0123 (object x < 0 ↔ X + 0.7Y < 13.0123); the disc is
// the silhouette of an ambient-1 grey sphere in front of it.
SceneDescription blocks_scene() {
  SceneDescription s = base_scene();
  s.camera = ortho_camera(40, 40, 20, -20);
  const Finish glow = finish_ambient_diffuse(1, 0);
  Object half = box_object({-1000, -1000, 0}, {0, 1000, 1}, texture(rgb(1, 1, 1), glow));
  const double phi = std::atan2(0.7, 1.0) * 180 / 3.14159265358979323846;
  const Vec3 on_line = Vec3{1, 0.7, 0} * (13.0123 / 1.49);
  half.world_from_object = Matrix::rotation_axis(2, phi) * Matrix::translation(on_line);
  s.objects.push_back(half);
  s.objects.push_back(sphere_object({30.017, -30.011, -1}, 7.3123, texture(rgb(0.5, 0.5, 0.5), glow)));
  return s;
}

// item7_aa_edge.pov: 4×1 image over x ∈ [0,4]; colour `left` for X < ex, `right` beyond (the background).
SceneDescription edge_scene(double ex, const Colour& left = rgb(1, 1, 1), const Colour& right = rgb(0, 0, 0)) {
  SceneDescription s = base_scene();
  s.camera = ortho_camera(4, 1, 2, -0.5);
  s.background = right;
  s.objects.push_back(box_object({-10, -10, 0}, {ex, 10, 1}, texture(left, finish_ambient_diffuse(1, 0))));
  return s;
}

RenderSettings aa_settings(int W, int H, int method, int depth = 3, double thr = 0.3, int block = 32) {
  RenderSettings r;
  r.width = W;
  r.height = H;
  r.threads = 1;
  r.antialias = true;
  r.jitter = false;
  r.sampling_method = method;
  r.antialias_depth = depth;
  r.antialias_threshold = thr;
  r.block_size = block;
  return r;
}

RenderResult render_scene(const SceneDescription& s, const RenderSettings& settings) {
  return povtrace::render::render(build_render_scene(s, BuildOptions{}), settings);
}

// Every pixel (all three channels) of `image` against the transcription, exactly; returns the number of mismatches.
int mismatches(const image::Image& image, const Pixels& expected, std::string* first) {
  int bad = 0;
  for (const auto& [xy, v] : expected)
    for (int ch = 0; ch < 3; ++ch) {
      // Same operations in the same order in double, then the framebuffer's float: bit-exact.
      const float got = image.pixel(xy.first, xy.second)[ch];
      if (got != static_cast<float>(v)) {
        if (bad++ == 0 && first)
          *first = "pixel (" + std::to_string(xy.first) + "," + std::to_string(xy.second) + ") got " +
                   std::to_string(got) + " expected " + std::to_string(v);
      }
    }
  return bad;
}

int fractional(const Pixels& p) {
  int n = 0;
  for (const auto& kv : p) n += kv.second != 0.0 && kv.second != 0.5 && kv.second != 1.0;
  return n;
}

TEST(AntialiasModel, ShadeFunctionMatchesTheTracer) {
  // The analytic shade function is what the tracer returns at pixel centres and at odd sub-positions.
  const RenderScene rs = build_render_scene(blocks_scene(), BuildOptions{});
  Tracer tracer(rs, ShadingModel::povray);
  int checked = 0;
  for (double sy = -1; sy < 40; sy += 0.37)
    for (double sx = -1; sx < 40; sx += 0.41) {
      const Radiance r = tracer.trace_camera_ray(*camera_ray(rs.camera, sx, sy, 40, 40));
      ASSERT_EQ(r.colour.x, shade_blocks(sx, sy)) << sx << "," << sy;
      ++checked;
    }
  EXPECT_GT(checked, 10000);
}

struct Case {
  const char* name;
  int method, depth;
  double thr;
  int block;
};

TEST(AntialiasModel, BlocksSceneMatchesTranscription) {
  // [V item7_aa_check] the option sets checked against POV-Ray, jitter off (POV-Ray's jitter lookup is checked by
  // runtime/jitter tests and the reference scenes aa_method1_jitter and aa_method2_jitter).
  const Case cases[] = {{"+A -J", 1, 3, 0.3, 32},       {"+A +BS8 -J", 1, 3, 0.3, 8},
                        {"+A0.1 +R2 -J", 1, 2, 0.1, 32}, {"+A0.0 -J", 1, 3, 0.0, 32},
                        {"+A +AM2 -J", 2, 3, 0.3, 32},  {"+A0.1 +AM2 +R4 -J", 2, 4, 0.1, 32},
                        {"+A +AM2 +BS8 -J", 2, 3, 0.3, 8}};
  const SceneDescription scene = blocks_scene();
  for (const Case& c : cases) {
    std::uint64_t calls = 0;
    const Shade counted = [&](double x, double y) {
      ++calls;
      return shade_blocks(x, y);
    };
    const Pixels expected = c.method == 1 ? method1(40, 40, counted, c.depth, c.thr, c.block)
                                          : method2(40, 40, counted, c.depth, c.thr);
    const RenderResult out = render_scene(scene, aa_settings(40, 40, c.method, c.depth, c.thr, c.block));
    std::string first;
    EXPECT_EQ(mismatches(out.image, expected, &first), 0) << c.name << ": " << first;
    EXPECT_GT(fractional(expected), 40) << c.name << ": the scene must exercise supersampling";
    // Method 1 traces exactly the transcription's samples (frame pixels included). Method 2 shares pixel corners
    // inside a block, so it traces fewer than the transcription, which re-traces every corner per pixel.
    if (c.method == 1)
      EXPECT_EQ(out.rays.camera, calls) << c.name;
    else
      EXPECT_LT(out.rays.camera, calls) << c.name;
  }
}

TEST(AntialiasModel, EdgeScenesMatchTranscription) {
  for (double ex : {1.4, 1.45, 1.55, 1.62}) {
    const Shade edge = [ex](double sx, double) { return sx + 0.5 < ex ? 1.0 : 0.0; };
    for (int method : {1, 2})
      for (int depth : {2, 3, 4}) {
        const Pixels expected = method == 1 ? method1(4, 1, edge, depth) : method2(4, 1, edge, depth);
        const RenderResult out = render_scene(edge_scene(ex), aa_settings(4, 1, method, depth));
        std::string first;
        EXPECT_EQ(mismatches(out.image, expected, &first), 0)
            << "edge " << ex << " method " << method << " depth " << depth << ": " << first;
      }
  }
}

TEST(AntialiasEdge, VerifiedValues) {
  // [V item7_aa_check] edge at 0.4 of pixel 1 (ex = 1.4), pixel (1,0), jitter off:
  // method 1, depth 3: sub-samples at X = 1.5 + {−1/3, 0, 1/3}: one white column of 3 + black centre → 3/10.
  // depth 2: X = 1.25 (white), 1.75 → (2 + 0)/5 = 0.4; depth 4: X = 1.125, 1.375 white → 8/17.
  // method 2, depth 3: corners white | black → halves: [1,1.5] = (1 + 1 + 0.5 + 0.5)/4 = 0.75, [1.5,2] = 0
  // → 0.375.
  const SceneDescription scene = edge_scene(1.4);
  EXPECT_FLOAT_EQ(render_scene(scene, aa_settings(4, 1, 1, 3)).image.pixel(1, 0)[0], 0.3f);
  EXPECT_FLOAT_EQ(render_scene(scene, aa_settings(4, 1, 1, 2)).image.pixel(1, 0)[0], 0.4f);
  EXPECT_FLOAT_EQ(render_scene(scene, aa_settings(4, 1, 1, 4)).image.pixel(1, 0)[0], static_cast<float>(8.0 / 17.0));
  EXPECT_FLOAT_EQ(render_scene(scene, aa_settings(4, 1, 2, 3)).image.pixel(1, 0)[0], 0.375f);
  // Without antialiasing: the centre sample only (X = 1.5 is black).
  RenderSettings plain = aa_settings(4, 1, 1);
  plain.antialias = false;
  EXPECT_EQ(render_scene(scene, plain).image.pixel(1, 0)[0], 0.0f);
  EXPECT_EQ(render_scene(scene, plain).image.pixel(0, 0)[0], 1.0f);
}

TEST(AntialiasEdge, ThresholdComparesGammaEncodedDistance) {
  // [V item7_aa_edge] red 0.5 left of the edge, red r right: distance |0.5^0.4 − r^0.4| = 0.290 for r = 0.1497
  // (< 0.3: no supersampling, pixel 1 keeps its centre value), 0.310 for r = 0.1342 (supersampled: 3 left + 7 right
  // samples of 10).
  EXPECT_NEAR(std::pow(0.5, 0.4) - std::pow(0.1497, 0.4), 0.290, 5e-4);
  EXPECT_NEAR(std::pow(0.5, 0.4) - std::pow(0.1342, 0.4), 0.310, 5e-4);
  RenderResult out = render_scene(edge_scene(1.4, rgb(0.5, 0, 0), rgb(0.1497, 0, 0)), aa_settings(4, 1, 1));
  EXPECT_FLOAT_EQ(out.image.pixel(1, 0)[0], 0.1497f);
  out = render_scene(edge_scene(1.4, rgb(0.5, 0, 0), rgb(0.1342, 0, 0)), aa_settings(4, 1, 1));
  EXPECT_FLOAT_EQ(out.image.pixel(1, 0)[0], static_cast<float>((3 * 0.5 + 7 * 0.1342) / 10));
}

TEST(AntialiasMethod1, FramePixelsAreTracedButNeverOutput) {
  // [V] "Pixels: 9" for a flat 4×1 image: 4 pixels + 4 frame pixels above + 1 to the left.
  SceneDescription s = edge_scene(-5);   // all background
  const RenderResult out = render_scene(s, aa_settings(4, 1, 1));
  EXPECT_EQ(out.rays.camera, 9u);
  // A 40×40 flat image in 32-px blocks: blocks 32×32, 8×32, 32×8, 8×8 → 1600 + (32+32) + (8+32) + (32+8) + (8+8).
  const RenderResult big = render_scene(s, aa_settings(40, 40, 1));
  EXPECT_EQ(big.rays.camera, 1600u + 64u + 40u + 40u + 16u);
}

bool same_image(const image::Image& a, const image::Image& b) { return a.rgba == b.rgba; }

TEST(AntialiasThreads, ImageIsBitIdenticalForAnyThreadCount) {
  const SceneDescription scene = blocks_scene();
  for (int method : {1, 2})
    for (bool jitter : {false, true}) {
      RenderSettings one = aa_settings(40, 40, method, 3, 0.3, 8);
      one.jitter = jitter;
      RenderSettings two = one;
      two.threads = 2;
      RenderSettings three = one;
      three.threads = 3;
      const RenderResult a = render_scene(scene, one), b = render_scene(scene, two), c = render_scene(scene, three);
      EXPECT_TRUE(same_image(a.image, b.image)) << "method " << method << " jitter " << jitter;
      EXPECT_TRUE(same_image(a.image, c.image)) << "method " << method << " jitter " << jitter;
      EXPECT_EQ(a.rays.camera, b.rays.camera);
      EXPECT_EQ(a.rays.camera, c.rays.camera);
    }
  // Without antialiasing too.
  RenderSettings plain = aa_settings(40, 40, 1);
  plain.antialias = false;
  RenderSettings plain2 = plain;
  plain2.threads = 2;
  EXPECT_TRUE(same_image(render_scene(scene, plain).image, render_scene(scene, plain2).image));
}

TEST(AntialiasJitter, DeterministicAndEffective) {
  const SceneDescription scene = blocks_scene();
  for (int method : {1, 2}) {
    RenderSettings s = aa_settings(40, 40, method);
    s.jitter = true;
    const RenderResult a = render_scene(scene, s), b = render_scene(scene, s);
    EXPECT_TRUE(same_image(a.image, b.image)) << "method " << method;
    s.jitter = false;
    const RenderResult c = render_scene(scene, s);
    EXPECT_FALSE(same_image(a.image, c.image)) << "method " << method << ": jitter changed nothing";
    // Jitter only moves sub-samples: pixels that were never supersampled are identical.
    int equal = 0;
    for (std::size_t i = 0; i < a.image.rgba.size(); ++i) equal += a.image.rgba[i] == c.image.rgba[i];
    EXPECT_GT(equal, static_cast<int>(a.image.rgba.size() / 2));
  }
}

}  // namespace

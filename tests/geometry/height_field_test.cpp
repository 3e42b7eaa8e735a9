// Height field: seeded random rays against brute force over every triangle of the grid (written here from the
// triangles' world-space corners), the flat and smooth normals, POV-Ray's inside rule, PNG heights and the located
// error for a missing image.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <random>

#include "geometry_kit.hpp"
#include "scene/source.hpp"
#include "renderer/image/image.hpp"
#include "renderer/image/jpeg_io.hpp"
#include "renderer/image/png_io.hpp"
#include "renderer/shapes/height_field.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

std::shared_ptr<HeightFieldData> random_field(std::mt19937& rng, int w, int d, bool smooth, double water = 0) {
  std::uniform_int_distribution<int> h(2000, 60000);
  std::vector<std::uint16_t> v(static_cast<std::size_t>(w) * d);
  for (auto& x : v) x = static_cast<std::uint16_t>(h(rng));
  return height_field_data(std::move(v), w, d, water, smooth);
}

struct Triangle {
  Vec3 a, b, c;
};

// The grid's triangles in world space: per cell the lower (x, z)(x+1, z)(x, z+1) and the upper one.
std::vector<Triangle> world_triangles(const HeightFieldData& f, const Matrix& m) {
  std::vector<Triangle> out;
  const Matrix unit = Matrix::scaling({1.0 / (f.width - 1), 1.0 / 65536, 1.0 / (f.depth - 1)}) * m;
  auto at = [&](int x, int z) { return unit.point(Vec3{double(x), f.height(x, z), double(z)}); };
  for (int z = 0; z + 1 < f.depth; ++z)
    for (int x = 0; x + 1 < f.width; ++x) {
      out.push_back({at(x, z), at(x + 1, z), at(x, z + 1)});
      out.push_back({at(x + 1, z + 1), at(x, z + 1), at(x + 1, z)});
    }
  return out;
}

// Möller–Trumbore; also how far inside the triangle the hit is (the smallest barycentric coordinate).
bool hit_triangle(const Triangle& t, const Ray& r, double& depth, double& margin) {
  const Vec3 e1 = t.b - t.a, e2 = t.c - t.a, p = cross(r.direction, e2);
  const double det = dot(e1, p);
  if (std::abs(det) < 1e-14) return false;
  const Vec3 s = r.origin - t.a;
  const double u = dot(s, p) / det;
  const Vec3 q = cross(s, e1);
  const double v = dot(r.direction, q) / det;
  depth = dot(e2, q) / det;
  margin = std::min({u, v, 1 - u - v});
  return margin >= 0 && depth > 1e-9;
}

TEST(HeightField, RandomRaysMatchBruteForceOverTheTriangles) {
  std::mt19937 rng(5150);
  std::uniform_real_distribution<double> u(0, 1), pos(-4, 4);
  int compared = 0, hits = 0;
  for (int k = 0; k < 600; ++k) {
    const bool smooth = k % 2;
    const auto f = random_field(rng, 3 + k % 7, 2 + k % 5, smooth);
    const Matrix m = k % 3 ? random_mirroring_transform(rng, 1) : Matrix::identity();
    const Primitive p = place_height_field(f, m);
    const auto tris = world_triangles(*f, m);
    const Vec3 target = m.point(Vec3{u(rng), u(rng), u(rng)});
    const Vec3 origin = m.point(Vec3{pos(rng), pos(rng) + 2, pos(rng)});
    const Ray r = ray(origin, target - origin);
    double best = tolerance::bound_huge, margin_at_best = 1;
    std::size_t best_index = 0;
    for (std::size_t i = 0; i < tris.size(); ++i) {
      double t = 0, margin = 0;
      if (hit_triangle(tris[i], r, t, margin) && t < best) best = t, margin_at_best = margin, best_index = i;
    }
    const std::optional<SurfaceHit> h = nearest_hit(p, r, tolerance::min_isect_depth, tolerance::bound_huge);
    const bool found = h.has_value();
    if (margin_at_best < 1e-3) continue;   // near a triangle's edge POV-Ray's 1e-4 slack may pick the neighbour
    ++compared;
    ASSERT_EQ(found, best < tolerance::bound_huge) << "ray " << k;
    if (!found) continue;
    ++hits;
    EXPECT_NEAR(h->t, best, 1e-9 * (1 + best)) << "ray " << k;
    EXPECT_EQ(h->element, best_index) << "ray " << k;
    const Triangle& t = tris[best_index];
    const Vec3 flat = normalize(cross(t.b - t.a, t.c - t.a));
    const Vec3 n = surface_normal(*h, r.origin + r.direction * h->t);
    EXPECT_NEAR(length(n), 1.0, 1e-12);
    if (!smooth) {
      EXPECT_NEAR(std::abs(dot(n, flat)), 1.0, 1e-9) << "ray " << k;
    }
  }
  EXPECT_GT(compared, 550);
  EXPECT_GT(hits, 300);
}

TEST(HeightField, SmoothNormalsOfAPlaneAreItsNormal) {
  // Heights rising along x only: every vertex normal is the plane's, whatever the interpolation.
  std::vector<std::uint16_t> v;
  for (int z = 0; z < 4; ++z)
    for (int x = 0; x < 5; ++x) v.push_back(static_cast<std::uint16_t>(10000 + 5000 * x));
  const Primitive p = place_height_field(height_field_data(v, 5, 4, 0, true), Matrix::identity());
  // In grid space the normal is (−5000, 1, 0) normalised; POV-Ray stores it as 16-bit integers 32767·n (truncated,
  // which leaves the small y component only 3 bits), and the grid's scaling <1/4, 1/65536, 1/3> carries it to world.
  const double len = std::sqrt(5000.0 * 5000.0 + 1.0);
  const double gx = static_cast<std::int16_t>(-32767 * 5000 / len), gy = static_cast<std::int16_t>(32767 / len);
  const Vec3 expected = normalize(Vec3{gx * 4, gy * 65536, 0});
  const Vec3 n = surface_normal(p, Vec3{0.3, (10000 + 5000 * 1.2) / 65536.0, 0.4});
  EXPECT_NEAR(dot(n, expected), 1.0, 1e-12);
  EXPECT_LT(dot(n, normalize(Vec3{-5000.0 * 4 / 65536, 1, 0})), 0.9997);   // the quantisation is visible
}

TEST(HeightField, InsideIsBelowTheSurfaceWithinTheGrid) {
  std::vector<std::uint16_t> v(9, 32768);
  Primitive p = place_height_field(height_field_data(v, 3, 3, 0, false), Matrix::identity());
  EXPECT_TRUE(inside(p, {0.5, 0.4, 0.5}));
  EXPECT_FALSE(inside(p, {0.5, 0.6, 0.5}));
  EXPECT_FALSE(inside(p, {1.0, 0.4, 0.5}));   // the far edge of the grid is outside
  EXPECT_FALSE(inside(p, {-0.1, 0.4, 0.5}));
  p.inverse = true;
  EXPECT_FALSE(inside(p, {0.5, 0.4, 0.5}));
  EXPECT_TRUE(inside(p, {0.5, 0.6, 0.5}));
}

TEST(HeightField, WaterLevelCutsTheBottom) {
  // All heights 0.25 except one peak: with water_level 0.5 the box starts at 0.5, so a ray at height 0.3 misses.
  std::vector<std::uint16_t> v(9, 16384);
  v[4] = 60000;
  const Primitive p = place_height_field(height_field_data(v, 3, 3, 0.5, false), Matrix::identity());
  std::optional<SurfaceHit> h;
  EXPECT_FALSE(nearest_hit(p, ray({-1, 0.3, 0.1}, {1, 0, 0}), 1e-4, 1e9));
  h = nearest_hit(p, ray({0.5, 2, 0.5}, {0, -1, 0}), 1e-4, 1e9);
  EXPECT_TRUE(h);
  EXPECT_TRUE(inside(p, {0.1, 0.3, 0.1}));   // below the water level: inside
}

TEST(HeightField, ARayLeavingAHitFindsNoHitAtTheSamePoint) {
  std::mt19937 rng(8);
  std::uniform_real_distribution<double> u(0.05, 0.95);
  for (int k = 0; k < 300; ++k) {
    const Primitive p = place_height_field(random_field(rng, 6, 6, false), Matrix::identity());
    const Ray r = ray({u(rng), 3, u(rng)}, {u(rng) - 0.5, -1, u(rng) - 0.5});
    const std::optional<SurfaceHit> first = nearest_hit(p, r, tolerance::min_isect_depth, tolerance::bound_huge);
    if (!first) continue;
    const Ray next{r.origin + r.direction * first->t, r.direction};
    const std::optional<SurfaceHit> second = nearest_hit(p, next, tolerance::min_isect_depth, tolerance::bound_huge);
    if (second) {
      EXPECT_NE(second->element, first->element) << "ray " << k;
    }
  }
}

// An 8-bit grey PNG through POV-Ray's grey chain: 0 and 255 map to the ends of the 16-bit range; the bottom image
// row is z = 0.
TEST(HeightField, GreyPngHeights) {
  const auto dir = std::filesystem::temp_directory_path() / "povtrace_hf_test";
  std::filesystem::create_directories(dir);
  image::Image img(2, 2);
  img.encoding = image::Encoding::encoded;
  const float values[4] = {0.0f, 1.0f, 128.0f / 255.0f, 64.0f / 255.0f};   // top row, then bottom row
  for (int i = 0; i < 4; ++i)
    for (int c = 0; c < 3; ++c) img.pixel(i % 2, i / 2)[c] = values[i];
  image::write_png(img, dir / "rgb.png", 8);
  HeightField h;
  h.file = (dir / "rgb.png").string();
  const Primitive p = make_height_field(h, Matrix::identity());
  const auto& f = static_cast<const HeightFieldData&>(*p.data);
  // An RGB PNG: (r·256 + g)·255 with r = g.
  EXPECT_EQ(f.height(0, 1), 0);
  EXPECT_EQ(f.height(1, 1), 65535);
  EXPECT_NEAR(f.height(0, 0), 128.0 / 255 * 257 * 255, 1.0);
  h.file = (dir / "missing.png").string();
  FileNames names;
  h.file_loc = SourceLoc{names.intern("scene.pov"), 7, 18};
  try {
    make_height_field(h, Matrix::identity());
    FAIL() << "a missing image must be an error";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.location().line, 7);
    EXPECT_EQ(e.location().column, 18);
    EXPECT_NE(e.bare_message().find("missing.png"), std::string::npos);
  }
  std::filesystem::remove_all(dir);
}

// A palette PNG: the height is the palette index · 256, whatever the colour (scenes/height_field_palette.png, whose
// palette runs from white at index 0 to black at 255; scripts/make_texture_images.py gives the indices).
TEST(HeightField, PalettePngHeightsAreTheIndicesTimes256) {
  const char* source = std::getenv("POVTRACE_SOURCE_DIR");
  ASSERT_NE(source, nullptr);
  HeightField h;
  h.file = (std::filesystem::path(source) / "scenes" / "height_field_palette.png").string();
  const Primitive p = make_height_field(h, Matrix::identity());
  const auto& f = static_cast<const HeightFieldData&>(*p.data);
  ASSERT_EQ(f.width, 24);
  ASSERT_EQ(f.depth, 18);
  // Sample (x, z) is image pixel (x, 17 - z).
  EXPECT_EQ(f.height(0, 0), 40 * 256);
  EXPECT_EQ(f.height(5, 0), 20 * 256);
  EXPECT_EQ(f.height(11, 9), 255 * 256);
  EXPECT_EQ(f.height(12, 8), 253 * 256);
  EXPECT_EQ(f.height(23, 17), 40 * 256);
}

// A JPEG: POV-Ray reads it as an 8-bit RGB image, the height (r·256 + g)·255 of the decoded red and green, as for
// an 8-bit RGB PNG (image_height_at). The file is one povtrace writes; its decoded bytes give the expected heights.
TEST(HeightField, JpegHeightsAreRedHighGreenLow) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "povtrace_hf_jpeg_test";
  std::filesystem::create_directories(dir);
  image::Image img(8, 6);
  img.encoding = image::Encoding::encoded;
  for (int y = 0; y < 6; ++y)
    for (int x = 0; x < 8; ++x) {
      float* px = &img.rgba[(static_cast<std::size_t>(y) * 8 + x) * 4];
      px[0] = static_cast<float>(x) / 8.0f;
      px[1] = static_cast<float>(y) / 6.0f;
      px[2] = 0.5f;
      px[3] = 1.0f;
    }
  image::EncodeOptions options;
  options.format = image::FileFormat::jpeg;
  options.jpeg_quality = 100;
  const std::string bytes = image::encode_image(img, options);
  const std::filesystem::path file = dir / "heights.jpg";
  std::ofstream(file, std::ios::binary).write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  const image::Image decoded = image::decode_jpeg(bytes);
  HeightField h;
  h.file = file.string();
  const Primitive p = make_height_field(h, Matrix::identity());
  const auto& f = static_cast<const HeightFieldData&>(*p.data);
  ASSERT_EQ(f.width, 8);
  ASSERT_EQ(f.depth, 6);
  for (int z = 0; z < 6; ++z)
    for (int x = 0; x < 8; ++x) {
      const float* px = decoded.pixel(x, 5 - z);   // sample (x, z) is image pixel (x, 5 - z)
      EXPECT_EQ(f.height(x, z), static_cast<std::uint16_t>((px[0] * 256.0 + px[1]) * 255.0)) << x << "," << z;
    }
  std::filesystem::remove_all(dir);
}

}  // namespace

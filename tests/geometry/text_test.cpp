// Text: seeded random rays against a brute-force answer that marches along the ray with a point-in-outline test
// of its own (the glyph outlines flattened into polygons, even-odd rule), the inside test against the same
// polygons, normals against the flattened outline, and rays leaving a hit.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <iterator>
#include <optional>
#include <random>

#include "runtime/truetype.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;

// The outline as polygons: quadratic pieces cut into kSteps straight segments (TrueType's rules: the first point
// of each contour used here is on the curve; two control points in a row imply the on-curve point between them).
constexpr int kSteps = 64;
using Polygon2 = std::vector<std::pair<double, double>>;

std::vector<Polygon2> flatten(const GlyphOutline& g) {
  std::vector<Polygon2> out;
  for (const GlyphContour& c : g.contours) {
    const std::size_t n = c.count();
    EXPECT_TRUE(c.on_curve[0]) << "the brute force expects contours that start on the curve";
    Polygon2 poly{{c.x[0], c.y[0]}};
    for (std::size_t j = 1; j <= n; ++j) {
      if (c.on_curve[j]) {
        poly.emplace_back(c.x[j], c.y[j]);
        continue;
      }
      const auto [x0, y0] = poly.back();
      double x2 = c.x[(j + 1) % (n + 1)], y2 = c.y[(j + 1) % (n + 1)];
      if (j == n) x2 = c.x[0], y2 = c.y[0];
      else if (!c.on_curve[j + 1]) x2 = (c.x[j] + x2) / 2, y2 = (c.y[j] + y2) / 2;
      for (int k = 1; k <= kSteps; ++k) {
        const double s = double(k) / kSteps, a = (1 - s) * (1 - s), b = 2 * s * (1 - s), d = s * s;
        poly.emplace_back(a * x0 + b * c.x[j] + d * x2, a * y0 + b * c.y[j] + d * y2);
      }
    }
    out.push_back(poly);
  }
  return out;
}

struct FlatGlyph {
  std::vector<Polygon2> polygons;
  double x, y;
};

bool in_polygons(const std::vector<Polygon2>& polys, double x, double y) {
  bool in = false;
  for (const Polygon2& p : polys)
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++)
      if ((p[i].second > y) != (p[j].second > y) &&
          x < (p[j].first - p[i].first) * (y - p[i].second) / (p[j].second - p[i].second) + p[i].first)
        in = !in;
  return in;
}

// Distance from (x, y) to the nearest polygon edge, and that edge's direction.
double edge_distance(const std::vector<Polygon2>& polys, double x, double y, double* dx = nullptr,
                     double* dy = nullptr) {
  double best = 1e30;
  for (const Polygon2& p : polys)
    for (std::size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
      const double ex = p[i].first - p[j].first, ey = p[i].second - p[j].second, len2 = ex * ex + ey * ey;
      if (len2 == 0) continue;
      const double s = std::clamp(((x - p[j].first) * ex + (y - p[j].second) * ey) / len2, 0.0, 1.0);
      const double d = std::hypot(p[j].first + s * ex - x, p[j].second + s * ey - y);
      if (d < best) {
        best = d;
        if (dx) *dx = ex, *dy = ey;
      }
    }
  return best;
}

struct Fixture {
  Text text;
  std::vector<FlatGlyph> flat;
  Matrix world_from_object = Matrix::rotation({10, -25, 5}) * Matrix::translation({0.3, -0.2, 0.5});
  Primitive prim;

  explicit Fixture(const std::string& string) {
    std::ifstream in("/usr/share/povray-3.7/include/cyrvetic.ttf", std::ios::binary);
    ttf::Font font({std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()}, ttf::StringEncoding::ascii);
    std::vector<std::uint32_t> codes(string.begin(), string.end());
    text = ttf::lay_out_text(font, codes, 0.4, {0, 0, 0});
    for (const TextGlyph& g : text.glyphs) flat.push_back({flatten(*g.outline), g.x, g.y});
    prim = make_text(text, world_from_object);
  }
  bool inside_object(Vec3 q) const {
    if (q.z < 0 || q.z > text.thickness) return false;
    for (const FlatGlyph& g : flat)
      if (in_polygons(g.polygons, q.x - g.x, q.y - g.y)) return true;
    return false;
  }
  double distance_to_walls(Vec3 q) const {
    double d = 1e30;
    for (const FlatGlyph& g : flat) d = std::min(d, edge_distance(g.polygons, q.x - g.x, q.y - g.y));
    return d;
  }
};

// The first change of inside along the object-space ray (step h, then bisection), or a negative depth.
double first_crossing(const Fixture& f, Vec3 o, Vec3 d, double length) {
  constexpr double h = 2e-3;
  bool was = f.inside_object(o + d * 1e-4);
  for (double t = h; t < length; t += h) {
    if (f.inside_object(o + d * t) == was) continue;
    double lo = t - h, hi = t;
    for (int k = 0; k < 50; ++k) {
      const double mid = (lo + hi) / 2;
      (f.inside_object(o + d * mid) == was ? lo : hi) = mid;
    }
    return hi;
  }
  return -1;
}

TEST(Text, NearestHitEqualsMarchingThroughTheOutline) {
  Fixture f("Ao");
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(0, 1);
  int agree = 0, hits = 0, rays = 300;
  const Matrix object_from_world = f.world_from_object.inverse();
  for (int k = 0; k < rays; ++k) {
    // Aim at a random point of the text's slab from a random point around it.
    const Vec3 target{u(rng) * 1.3, u(rng) * 0.8 - 0.1, u(rng) * 0.4};
    const Vec3 origin{u(rng) * 4 - 1.5, u(rng) * 4 - 1.5, u(rng) < 0.5 ? -2.0 : 2.4};
    const Vec3 world_o = f.world_from_object.point(origin), world_t = f.world_from_object.point(target);
    const Ray ray{world_o, normalize(world_t - world_o)};
    const Vec3 local_d = object_from_world.vector(ray.direction);
    const double brute = first_crossing(f, origin, local_d, 8.0);
    const std::optional<SurfaceHit> hit = nearest_hit(f.prim, ray, 1e-6, 1e9);
    if (hit) ++hits;
    if (hit.has_value() == (brute > 0) && (!hit || std::abs(hit->t - brute) < 2e-3)) ++agree;
  }
  EXPECT_GT(hits, 100);
  EXPECT_GE(agree, rays - 3);   // grazing rays may part ways by the flattening's error
}

TEST(Text, InsideMatchesThePolygonTest) {
  Fixture f("Ao");
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(0, 1);
  int inside_count = 0;
  for (int k = 0; k < 4000; ++k) {
    const Vec3 q{u(rng) * 1.4 - 0.05, u(rng) * 0.9 - 0.15, u(rng) * 0.6 - 0.1};
    if (f.distance_to_walls(q) < 2e-3 || std::abs(q.z) < 1e-9 || std::abs(q.z - 0.4) < 1e-9) continue;
    const bool expected = f.inside_object(q);
    inside_count += expected;
    EXPECT_EQ(inside(f.prim, f.world_from_object.point(q)), expected) << q.x << " " << q.y << " " << q.z;
  }
  EXPECT_GT(inside_count, 200);
  Primitive inverted = f.prim;
  inverted.inverse = true;
  const Vec3 stroke = f.world_from_object.point({0.02, 0.01, 0.2});
  EXPECT_NE(inside(inverted, stroke), inside(f.prim, stroke));
}

TEST(Text, NormalsAreThoseOfTheFaceOrWallHit) {
  Fixture f("Ao");
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  int walls = 0;
  for (int k = 0; k < 400; ++k) {
    const Vec3 target{u(rng) * 1.3, u(rng) * 0.8 - 0.1, u(rng) * 0.4};
    const Vec3 origin{u(rng) * 4 - 1.5, u(rng) * 4 - 1.5, u(rng) * 4 - 1.8};
    const Vec3 wo = f.world_from_object.point(origin);
    const Ray ray{wo, normalize(f.world_from_object.point(target) - wo)};
    const std::optional<SurfaceHit> hit = nearest_hit(f.prim, ray, 1e-6, 1e9);
    if (!hit) continue;
    // Back to text space: the world normal is W⁻ᵀ n, so W's own matrix as "the inverse" undoes it.
    const Vec3 n = f.world_from_object.normal_from_inverse(surface_normal(*hit, ray.origin + ray.direction * hit->t));
    const Vec3 q = f.world_from_object.inverse().point(ray.origin + ray.direction * hit->t);
    EXPECT_NEAR(length(surface_normal(*hit, {})), 1.0, 1e-12);
    if (std::abs(q.z) < 1e-7 || std::abs(q.z - 0.4) < 1e-7) {   // a face: the normal is ±z in text space
      EXPECT_NEAR(std::abs(normalize(n).z), 1.0, 1e-9);
      continue;
    }
    double ex = 0, ey = 0;
    if (f.distance_to_walls(q) > 1e-4) continue;
    for (const FlatGlyph& g : f.flat) {
      double gx = 0, gy = 0;
      if (edge_distance(g.polygons, q.x - g.x, q.y - g.y, &gx, &gy) < 1e-4) ex = gx, ey = gy;
    }
    const Vec3 nn = normalize(n);
    EXPECT_NEAR(nn.z, 0.0, 1e-9);
    EXPECT_LT(std::abs(nn.x * ex + nn.y * ey) / std::hypot(ex, ey), 0.05);   // perpendicular to the outline
    ++walls;
  }
  EXPECT_GT(walls, 20);
}

TEST(Text, RaysLeavingAHitMeetTheNextSurfaceNotTheSameOne) {
  Fixture f("Ao");
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(0, 1);
  const Matrix object_from_world = f.world_from_object.inverse();
  int tested = 0, agree = 0;
  for (int k = 0; k < 300; ++k) {
    const Vec3 target{u(rng) * 1.3, u(rng) * 0.8 - 0.1, u(rng) * 0.4};
    const Vec3 origin{u(rng) * 4 - 1.5, u(rng) * 4 - 1.5, -2.0};
    const Vec3 wo = f.world_from_object.point(origin);
    const Ray ray{wo, normalize(f.world_from_object.point(target) - wo)};
    const std::optional<SurfaceHit> first = nearest_hit(f.prim, ray, tolerance::min_isect_depth, 1e9);
    if (!first) continue;
    const Ray on{ray.origin + ray.direction * first->t, ray.direction};
    HitBuffer all;
    collect_hits(f.prim, on, all);
    for (const SurfaceHit& h : all) EXPECT_GT(h.t, 1e-6);   // POV-Ray's own depth tolerance
    // The next surface along the ray is the next change of inside the brute force finds, not the one left.
    const std::optional<SurfaceHit> next = nearest_hit(f.prim, on, 1e-6, 1e9);
    const bool found = next.has_value();
    const Vec3 local_o = object_from_world.point(on.origin), local_d = object_from_world.vector(on.direction);
    const double brute = first_crossing(f, local_o, local_d, 8.0);
    if (found == (brute > 0) && (!found || std::abs(next->t - brute) < 2e-3)) ++agree;
    ++tested;
  }
  EXPECT_GT(tested, 100);
  EXPECT_GE(agree, tested - 3);
}

}  // namespace

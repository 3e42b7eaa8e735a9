// Prism: seeded random closed outlines of every spline kind, swept straight or conically, and random rays against
// marching on membership (between the heights and inside the outline, drawn independently: sweep_kit.hpp);
// normals against the outline's tangent or the end planes, POV-Ray's inside rule, rays leaving a hit, open and
// unclosed prisms.
#include <gtest/gtest.h>
#include <optional>

#include "renderer/shapes/solid_shapes.hpp"
#include "renderer/shapes/sweep.hpp"
#include "sweep_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

struct PrismCase {
  Prism prism;
  std::vector<std::array<Point2, 2>> edges;
  Point2 lo{1e300, 1e300}, hi{-1e300, -1e300};   // the outline's extent
};

// A star-shaped closed outline around the origin through `n` corners, with the control points each spline kind
// needs (quadratic: one before; cubic: one before and one after; Bézier: two per side).
std::vector<Point2> random_outline(std::mt19937& rng, SplineKind kind) {
  std::uniform_real_distribution<double> radius(0.5, 1.5), jitter(-0.3, 0.3), u(0, 1);
  const int n = 3 + static_cast<int>(u(rng) * 5);
  std::vector<Point2> c;
  for (int k = 0; k < n; ++k) {
    const double a = 2 * M_PI * (k + 0.5 * u(rng)) / n, r = radius(rng);
    c.push_back({r * std::cos(a), r * std::sin(a)});
  }
  const Point2 first = c.front(), second = c[1], last = c.back();
  switch (kind) {
    case SplineKind::linear: c.push_back(first); return c;
    case SplineKind::quadratic: c.insert(c.begin(), last); c.push_back(first); return c;
    case SplineKind::cubic: c.insert(c.begin(), last); c.push_back(first); c.push_back(second); return c;
    case SplineKind::bezier: {
      std::vector<Point2> p;
      for (int k = 0; k < n; ++k) {
        const Point2 a = c[k], b = c[(k + 1) % n];
        p.insert(p.end(), {a, {a[0] + (b[0] - a[0]) / 3 + jitter(rng), a[1] + (b[1] - a[1]) / 3 + jitter(rng)},
                           {a[0] + 2 * (b[0] - a[0]) / 3 + jitter(rng), a[1] + 2 * (b[1] - a[1]) / 3 + jitter(rng)},
                           b});
      }
      return p;
    }
  }
  return c;
}

PrismCase make_case(std::vector<Point2> points, SplineKind kind, bool conic, double h1, double h2, bool sturm) {
  PrismCase c;
  c.prism.spline = kind;
  c.prism.conic = conic;
  c.prism.height1 = h1;
  c.prism.height2 = h2;
  c.prism.sturm = sturm;
  c.prism.segment_starts = std::make_shared<const std::vector<std::uint32_t>>(*prism_segment_starts(kind, points));
  c.edges = polyline(kind, points, *c.prism.segment_starts);
  for (const auto& e : c.edges)
    for (int i = 0; i < 2; ++i) c.lo[i] = std::min(c.lo[i], e[0][i]), c.hi[i] = std::max(c.hi[i], e[0][i]);
  c.prism.points = profile(std::move(points));
  return c;
}

// The outline point (u, v) a prism-space point maps to (divided by y for a conic sweep).
Point2 outline_point(const Prism& p, Vec3 q) { return p.conic ? Point2{q.x / q.y, q.z / q.y} : Point2{q.x, q.z}; }

bool member(const PrismCase& c, Vec3 q) {
  if (!(q.y >= c.prism.height1 && q.y <= c.prism.height2)) return false;
  const Point2 o = outline_point(c.prism, q);
  if (o[0] < c.lo[0] || o[0] > c.hi[0] || o[1] < c.lo[1] || o[1] > c.hi[1]) return false;   // quick
  return crossings_right(c.edges, o[0], o[1]) % 2 == 1;
}

TEST(Prism, ASquareOutlineGivesABox) {
  const PrismCase c = make_case({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}, SplineKind::linear, false, 0, 2,
                                false);
  const Primitive p = make_prism(c.prism, Matrix::identity());
  HitBuffer hits;
  collect_hits(p, ray({-5, 0.5, 0.2}, {1, 0, 0}), hits);
  ASSERT_EQ(hits.size(), 2u);
  std::sort(hits.begin(), hits.end(), [](auto& a, auto& b) { return a.t < b.t; });
  EXPECT_NEAR(hits[0].t, 4, 1e-12);
  EXPECT_NEAR(hits[1].t, 6, 1e-12);
  EXPECT_NEAR(std::fabs(surface_normal(hits[0], {-1, 0.5, 0.2}).x), 1, 1e-12);
  const std::optional<SurfaceHit> top = nearest_hit(p, ray({0.2, 5, 0.3}, {0, -1, 0}), tolerance::min_isect_depth,
                                                    1e10);
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->t, 3, 1e-12);
  EXPECT_EQ(top->element, cap_element);
  EXPECT_NEAR(surface_normal(*top, {0.2, 2, 0.3}).y, 1, 1e-12);
  EXPECT_TRUE(inside(p, {0, 1, 0}));
  EXPECT_TRUE(inside(p, {0, 0, 0}));    // H1 ≤ y
  EXPECT_FALSE(inside(p, {0, 2, 0}));   // y < H2
  EXPECT_FALSE(inside(p, {1.5, 1, 0}));
}

TEST(Prism, OpenPrismsHaveNoEndPlanesButAnInside) {
  PrismCase c = make_case({{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}}, SplineKind::linear, false, 0, 2, false);
  c.prism.open = true;
  const Primitive p = make_prism(c.prism, Matrix::identity());
  const std::optional<SurfaceHit> h = nearest_hit(p, ray({0.2, 2.5, 0.3}, {0.5, -1, 0}), tolerance::min_isect_depth,
                                                  1e10);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t * normalize(Vec3{0.5, -1, 0}).x, 0.8, 1e-12);   // the wall x = 1, through the open top
  EXPECT_NE(h->element, cap_element);
  EXPECT_NE(h->element, base_element);
  EXPECT_TRUE(inside(p, {0, 1, 0}));
}

TEST(Prism, AnUnclosedOutlineIsNeverHit) {
  PrismCase c = make_case({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, SplineKind::bezier, false, 0, 1, false);
  c.prism.degenerate = true;
  const Primitive p = make_prism(c.prism, Matrix::identity());
  EXPECT_FALSE(nearest_hit(p, ray({0.5, 5, 0.5}, {0, -1, 0}), tolerance::min_isect_depth, 1e10));
}

TEST(Prism, RandomRaysMatchMarchingOnTheOutline) {
  std::mt19937 rng(4242);
  std::uniform_real_distribution<double> pos(-4, 4), u(0, 1);
  const SplineKind kinds[] = {SplineKind::linear, SplineKind::quadratic, SplineKind::cubic, SplineKind::bezier};
  int compared = 0, hits = 0, caps = 0, seconds = 0;
  for (int k = 0; k < 1000; ++k) {
    const SplineKind kind = kinds[k % 4];
    const bool conic = k % 8 >= 4;
    const double h1 = conic ? 0.2 + 0.5 * u(rng) : pos(rng) / 4, h2 = h1 + 0.3 + 1.5 * u(rng);
    const PrismCase c = make_case(random_outline(rng, kind), kind, conic, h1, h2, u(rng) < 0.3);
    const Matrix m = k % 3 ? random_transform(rng) : Matrix::identity();
    const Matrix inv = m.inverse();
    const Primitive p = make_prism(c.prism, m);
    auto in = [&](Vec3 w) { return member(c, inv.point(w)); };
    const Vec3 origin = m.point(Vec3{pos(rng), pos(rng), pos(rng)});
    const Ray r = ray(origin, m.point(Vec3{u(rng) - 0.5, h1 + (h2 - h1) * u(rng), u(rng) - 0.5}) - origin);
    const std::vector<double> ref = crossings(in, r, 0.0, 80.0, 40000);
    const std::optional<SurfaceHit> h = nearest_hit(p, r, tolerance::min_isect_depth, tolerance::bound_huge);
    const bool found = h.has_value();
    if (found != !ref.empty() || (ref.size() >= 2 && ref[1] - ref[0] < 1e-2) || grazes(p, r)) continue;
    ++compared;
    if (!found) continue;
    ++hits;
    ASSERT_NEAR(h->t, ref[0], 2e-5 * (1 + ref[0])) << "ray " << k;
    const Vec3 hit = r.origin + r.direction * h->t, q = inv.point(hit);
    Vec3 n{0, 1, 0};
    if (h->element == cap_element || h->element == base_element) {
      ++caps;
      EXPECT_NEAR(q.y, h->element == cap_element ? h2 : h1, 1e-9) << "ray " << k;
    } else {
      Point2 t{};
      const Point2 o = outline_point(c.prism, q);
      distance_to(c.edges, o[0], o[1], &t);
      n = Vec3{t[1], 0, -t[0]};
      if (conic) n.y = -(q.x * n.x + q.z * n.z) / q.y;   // the cone's normal: orthogonal to the ray from the apex
    }
    EXPECT_NEAR(std::fabs(dot(surface_normal(*h, hit), world_normal(m, n))), 1.0, 2e-4) << "ray " << k;
    const std::optional<SurfaceHit> next = nearest_hit(p, Ray{hit, r.direction}, tolerance::min_isect_depth,
                                                       tolerance::bound_huge);
    const bool again = next.has_value();
    if (ref.size() < 2 || (ref.size() > 2 && ref[2] - ref[1] < 1e-2)) continue;
    ++seconds;
    ASSERT_TRUE(again) << "ray " << k;
    EXPECT_NEAR(next->t, ref[1] - ref[0], 2e-5 * (1 + ref[1])) << "ray " << k;
  }
  EXPECT_GT(compared, 700);
  EXPECT_GT(hits, 400);
  EXPECT_GT(caps, 50);
  EXPECT_GT(seconds, 300);
}

TEST(Prism, InsideIsBetweenTheHeightsWithinTheOutline) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-2, 2), u(0, 1);
  const SplineKind kinds[] = {SplineKind::linear, SplineKind::quadratic, SplineKind::cubic, SplineKind::bezier};
  int insides = 0;
  for (int k = 0; k < 400; ++k) {
    const bool conic = k % 2;
    const PrismCase c = make_case(random_outline(rng, kinds[k % 4]), kinds[k % 4], conic, 0.3, 1.5, u(rng) < 0.5);
    const Matrix m = random_transform(rng);
    const Primitive p = make_prism(c.prism, m);
    for (int j = 0; j < 20; ++j) {
      const Vec3 q{pos(rng), 2 * u(rng), pos(rng)};
      const Point2 o = outline_point(c.prism, q);
      Point2 t{};
      if (distance_to(c.edges, o[0], o[1], &t) < 1e-4 || std::fabs(q.y - 0.3) < 1e-4 || std::fabs(q.y - 1.5) < 1e-4)
        continue;
      const bool expected = member(c, q);
      EXPECT_EQ(inside(p, m.point(q)), expected) << "prism " << k << " point " << j;
      insides += expected;
    }
  }
  EXPECT_GT(insides, 500);
}

}  // namespace

// Lathe: seeded random profiles of every spline kind (closed at the axis) and random rays against marching on the
// parity of profile crossings in the (radius, height) plane, with the profile drawn independently (sweep_kit.hpp);
// normals against the profile's tangent there, POV-Ray's inside rule, rays leaving a hit, the horizontal-ray path.
#include <gtest/gtest.h>
#include <optional>

#include "renderer/shapes/solid_shapes.hpp"
#include "sweep_kit.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::render;
using namespace povtrace::test;

struct LatheCase {
  Lathe lathe;
  std::vector<Point2> points;
  std::vector<std::array<Point2, 2>> edges;   // the profile in the (|x|, y) plane
  double r_lo = 1e300, r_hi = -1e300, y_lo = 1e300, y_hi = -1e300;
};

// Curve points from (0, y0) out and back to the axis; the spline kind decides the control points around them.
std::vector<Point2> random_points(std::mt19937& rng, SplineKind kind) {
  std::uniform_real_distribution<double> x(0.3, 1.5), step(-0.3, 1.0), u(0, 1);
  const int inner = 2 + static_cast<int>(u(rng) * 4);
  std::vector<Point2> curve{{0, 0}};
  for (int k = 0; k < inner; ++k) curve.push_back({x(rng), curve.back()[1] + step(rng)});
  curve.push_back({0, curve.back()[1] + 0.3 + u(rng)});
  if (kind == SplineKind::linear) return curve;
  if (kind == SplineKind::bezier) {
    std::vector<Point2> p;
    for (std::size_t k = 0; k + 1 < curve.size(); ++k)
      p.insert(p.end(), {curve[k], {x(rng), curve[k][1] + step(rng)}, {x(rng), curve[k + 1][1] + step(rng)},
                         curve[k + 1]});
    return p;
  }
  curve.insert(curve.begin(), Point2{0, -0.3});
  if (kind == SplineKind::cubic) curve.push_back({0, curve.back()[1] + 0.3});
  return curve;
}

LatheCase make_case(std::vector<Point2> points, SplineKind kind, bool sturm) {
  LatheCase c;
  c.points = points;
  c.lathe.spline = kind;
  c.lathe.sturm = sturm;
  c.lathe.points = profile(points);
  const std::size_t n = points.size();
  const auto starts = kind == SplineKind::bezier ? consecutive_starts(n / 4, 4)
                                                 : consecutive_starts(n - (kind == SplineKind::linear ? 1
                                                                           : kind == SplineKind::quadratic ? 2 : 3));
  c.edges = polyline(kind, points, starts);
  for (auto& e : c.edges)
    for (auto& p : e) {
      c.r_lo = std::min(c.r_lo, p[0]), c.r_hi = std::max(c.r_hi, p[0]);
      c.y_lo = std::min(c.y_lo, p[1]), c.y_hi = std::max(c.y_hi, p[1]);
      p[0] = std::fabs(p[0]);
    }
  return c;
}

bool profile_stays_off_negative_x(const LatheCase& c) { return c.r_lo > -1e-9; }

// Odd number of profile crossings outwards from the point (the solid POV-Ray's inside rule describes).
bool member(const LatheCase& c, Vec3 q) {
  const double radius = std::sqrt(q.x * q.x + q.z * q.z);
  if (q.y < c.y_lo || q.y > c.y_hi || radius > c.r_hi) return false;   // no crossings out there: quick
  return crossings_right(c.edges, radius, q.y) % 2 == 1;
}

TEST(Lathe, ACylinderProfileGivesTheCylinder) {
  const LatheCase c = make_case({{0, 0}, {1, 0}, {1, 2}, {0, 2}}, SplineKind::linear, false);
  const Primitive p = make_lathe(c.lathe, Matrix::identity());
  HitBuffer hits;
  collect_hits(p, ray({-5, 1, 0.5}, {1, 0.01, 0}), hits);
  ASSERT_EQ(hits.size(), 2u);
  std::sort(hits.begin(), hits.end(), [](auto& a, auto& b) { return a.t < b.t; });
  const double dx = std::sqrt(1 - 0.25);
  EXPECT_NEAR(hits[0].t * normalize(Vec3{1, 0.01, 0}).x, 5 - dx, 1e-12);
  EXPECT_NEAR(hits[1].t * normalize(Vec3{1, 0.01, 0}).x, 5 + dx, 1e-12);
  const Vec3 at = Vec3{-5, 1, 0.5} + normalize(Vec3{1, 0.01, 0}) * hits[0].t;
  EXPECT_NEAR(dot(surface_normal(hits[0], at), normalize(Vec3{at.x, 0, at.z})), 1.0, 1e-12);
  const std::optional<SurfaceHit> top = nearest_hit(p, ray({0.3, 5, 0}, {0, -1, 0}), tolerance::min_isect_depth, 1e10);
  ASSERT_TRUE(top);
  EXPECT_NEAR(top->t, 3, 1e-12);   // the top "segment" (1, 2) → (0, 2) is the cap
  EXPECT_NEAR(std::fabs(surface_normal(*top, {0.3, 2, 0}).y), 1, 1e-12);
  EXPECT_TRUE(inside(p, {0.5, 1, 0}));
  EXPECT_FALSE(inside(p, {0.5, 2.5, 0}));
  EXPECT_FALSE(inside(p, {1.2, 1, 0}));
}

TEST(Lathe, AHorizontalRayUsesTheRadiusEquation) {
  // |Dy| ≤ 1e-10: the segment roots come from r·u² = 0, each giving the two ray points at radius |x(w)|.
  const LatheCase c = make_case({{0, 0}, {1, 0}, {1.5, 2}, {0, 2}}, SplineKind::linear, false);
  const Primitive p = make_lathe(c.lathe, Matrix::identity());
  const std::optional<SurfaceHit> h = nearest_hit(p, ray({-5, 1, 0}, {1, 0, 0}), tolerance::min_isect_depth, 1e10);
  ASSERT_TRUE(h);
  EXPECT_NEAR(h->t, 5 - 1.25, 1e-9);
  EXPECT_EQ(h->element, 1u);
  EXPECT_NEAR(h->u, 0.5, 1e-9);
}

TEST(Lathe, RandomRaysMatchMarchingOnTheProfile) {
  std::mt19937 rng(1312);
  std::uniform_real_distribution<double> pos(-4, 4), u(0, 1);
  const SplineKind kinds[] = {SplineKind::linear, SplineKind::quadratic, SplineKind::cubic, SplineKind::bezier};
  int compared = 0, hits = 0, seconds = 0;
  for (int k = 0; k < 800; ++k) {
    const SplineKind kind = kinds[k % 4];
    const LatheCase c = make_case(random_points(rng, kind), kind, u(rng) < 0.3);
    if (!profile_stays_off_negative_x(c)) continue;
    const Matrix m = k % 3 ? random_transform(rng) : Matrix::identity();
    const Matrix inv = m.inverse();
    const Primitive p = make_lathe(c.lathe, m);
    auto in = [&](Vec3 w) { return member(c, inv.point(w)); };
    const Vec3 origin = m.point(Vec3{pos(rng), pos(rng) + 1.5, pos(rng)});
    const Ray r = ray(origin, m.point(Vec3{u(rng) - 0.5, 1.5 * u(rng), u(rng) - 0.5}) - origin);
    const std::vector<double> ref = crossings(in, r, 0.0, 80.0, 40000);
    const std::optional<SurfaceHit> h = nearest_hit(p, r, tolerance::min_isect_depth, tolerance::bound_huge);
    const bool found = h.has_value();
    if (found != !ref.empty() || (ref.size() >= 2 && ref[1] - ref[0] < 1e-2) || grazes(p, r)) continue;
    ++compared;
    if (!found) continue;
    ++hits;
    ASSERT_NEAR(h->t, ref[0], 2e-5 * (1 + ref[0])) << "ray " << k;
    // The normal: the profile's tangent at the hit, turned about the axis.
    const Vec3 hit = r.origin + r.direction * h->t, q = inv.point(hit);
    const double radius = std::sqrt(q.x * q.x + q.z * q.z);
    Point2 t{};
    distance_to(c.edges, radius, q.y, &t);
    const Vec3 n{t[1] * q.x / radius, -t[0], t[1] * q.z / radius};
    EXPECT_NEAR(std::fabs(dot(surface_normal(*h, hit), world_normal(m, n))), 1.0, 2e-4) << "ray " << k;
    // Leaving the hit along the ray finds the next crossing, not the same surface again.
    const std::optional<SurfaceHit> next = nearest_hit(p, Ray{hit, r.direction}, tolerance::min_isect_depth,
                                                       tolerance::bound_huge);
    const bool again = next.has_value();
    if (ref.size() < 2 || ref[1] - ref[0] < 1e-3 || (ref.size() > 2 && ref[2] - ref[1] < 1e-2)) continue;
    ++seconds;
    ASSERT_TRUE(again) << "ray " << k;
    EXPECT_NEAR(next->t, ref[1] - ref[0], 2e-5 * (1 + ref[1])) << "ray " << k;
  }
  EXPECT_GT(compared, 500);
  EXPECT_GT(hits, 250);
  EXPECT_GT(seconds, 150);
}

TEST(Lathe, InsideIsTheProfileParityWithinItsExtent) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> pos(-2, 2), u(0, 1);
  const SplineKind kinds[] = {SplineKind::linear, SplineKind::quadratic, SplineKind::cubic, SplineKind::bezier};
  int insides = 0;
  for (int k = 0; k < 400; ++k) {
    const LatheCase c = make_case(random_points(rng, kinds[k % 4]), kinds[k % 4], u(rng) < 0.5);
    if (!profile_stays_off_negative_x(c)) continue;
    const Matrix m = random_transform(rng);
    const Primitive p = make_lathe(c.lathe, m);
    for (int j = 0; j < 20; ++j) {
      const Vec3 q{pos(rng), c.y_lo + (c.y_hi - c.y_lo) * (1.4 * u(rng) - 0.2), pos(rng)};
      const double radius = std::sqrt(q.x * q.x + q.z * q.z);
      Point2 t{};
      if (distance_to(c.edges, radius, q.y, &t) < 1e-4) continue;
      const bool expected = member(c, q) && q.y >= c.y_lo && q.y <= c.y_hi && radius <= c.r_hi;
      EXPECT_EQ(inside(p, m.point(q)), expected) << "lathe " << k << " point " << j;
      insides += expected;
      Primitive flipped = p;
      flipped.inverse = true;
      EXPECT_EQ(inside(flipped, m.point(q)), !expected);
    }
  }
  EXPECT_GT(insides, 500);
}

TEST(Lathe, AnEmptyBezierLatheIsNeverHit) {
  Lathe l;
  l.spline = SplineKind::bezier;
  l.points = profile({});
  const Primitive p = make_lathe(l, Matrix::identity());
  const std::optional<SurfaceHit> h = nearest_hit(p, ray({0, 0, -5}, {0, 0, 1}), tolerance::min_isect_depth, 1e10);
  EXPECT_FALSE(h);
  EXPECT_FALSE(inside(p, {0, 0, 0}));
  EXPECT_TRUE(world_bounds(p).empty());
}

}  // namespace

// Helpers for the lathe, prism and sor tests: seeded random profiles, and an independent reference for each shape
// — the spline curves evaluated from their textbook definitions (lerp, the quadratic through P1 with slope
// (P2 − P0)/2, Catmull-Rom as a Hermite curve, de Casteljau for Bézier), sampled densely, and membership tests
// written from the shapes' definitions (parity of profile crossings; the sor's r² as a Hermite cubic in y).
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include "scene/description.hpp"
#include "quadric_kit.hpp"

namespace povtrace::test {

using Point2 = std::array<double, 2>;

inline Point2 lerp2(Point2 a, Point2 b, double t) { return {a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t}; }

// The point w ∈ [0, 1] of the segment of `spline` whose window of points starts at `p`.
inline Point2 spline_point(SplineKind spline, const Point2* p, double w, bool reversed_bezier = false) {
  switch (spline) {
    case SplineKind::linear: return lerp2(p[0], p[1], w);
    case SplineKind::quadratic: {
      Point2 out{};
      for (int i = 0; i < 2; ++i) {
        const double slope = 0.5 * (p[2][i] - p[0][i]);
        out[i] = p[1][i] + w * slope + w * w * (p[2][i] - p[1][i] - slope);
      }
      return out;
    }
    case SplineKind::cubic: {
      const double h00 = 2 * w * w * w - 3 * w * w + 1, h10 = w * w * w - 2 * w * w + w;
      const double h01 = -2 * w * w * w + 3 * w * w, h11 = w * w * w - w * w;
      Point2 out{};
      for (int i = 0; i < 2; ++i)
        out[i] = h00 * p[1][i] + h10 * 0.5 * (p[2][i] - p[0][i]) + h01 * p[2][i] + h11 * 0.5 * (p[3][i] - p[1][i]);
      return out;
    }
    case SplineKind::bezier: {
      if (reversed_bezier) w = 1.0 - w;
      const Point2 a = lerp2(p[0], p[1], w), b = lerp2(p[1], p[2], w), c = lerp2(p[2], p[3], w);
      return lerp2(lerp2(a, b, w), lerp2(b, c, w), w);
    }
  }
  return {};
}

// A dense polyline through every segment (windows starting at `starts`).
inline std::vector<std::array<Point2, 2>> polyline(SplineKind spline, const std::vector<Point2>& points,
                                                   const std::vector<std::uint32_t>& starts, int samples = 600) {
  std::vector<std::array<Point2, 2>> edges;
  for (const auto s : starts)
    for (int k = 0; k < samples; ++k)
      edges.push_back({spline_point(spline, &points[s], double(k) / samples),
                       spline_point(spline, &points[s], double(k + 1) / samples)});
  return edges;
}

// Crossings of the half-line from (u, v) towards +u with the polyline.
inline int crossings_right(const std::vector<std::array<Point2, 2>>& edges, double u, double v) {
  int n = 0;
  for (const auto& e : edges) {
    if ((e[0][1] > v) == (e[1][1] > v)) continue;
    const double x = e[0][0] + (v - e[0][1]) / (e[1][1] - e[0][1]) * (e[1][0] - e[0][0]);
    if (x >= u) ++n;
  }
  return n;
}

// The distance from (u, v) to the polyline, and the tangent of the nearest edge.
inline double distance_to(const std::vector<std::array<Point2, 2>>& edges, double u, double v, Point2* tangent) {
  double best = 1e300;
  for (const auto& e : edges) {
    const double dx = e[1][0] - e[0][0], dy = e[1][1] - e[0][1], len2 = dx * dx + dy * dy;
    const double s = len2 > 0 ? std::clamp(((u - e[0][0]) * dx + (v - e[0][1]) * dy) / len2, 0.0, 1.0) : 0.0;
    const double px = e[0][0] + s * dx - u, py = e[0][1] + s * dy - v, d = std::sqrt(px * px + py * py);
    if (d < best) best = d, *tangent = {dx, dy};
  }
  return best;
}

// Whether the shape's two nearest hits along the ray lie closer than `gap` (a grazing ray the marching reference,
// stepping more coarsely, may see as no crossing at all).
inline bool grazes(const render::Primitive& p, const render::Ray& r, double gap = 1e-2) {
  render::HitBuffer all;
  render::collect_hits(p, r, all);
  std::sort(all.begin(), all.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
  for (std::size_t k = 0; k + 1 < all.size() && k < 2; ++k)
    if (all[k + 1].t - all[k].t < gap) return true;
  return false;
}

inline std::vector<std::uint32_t> consecutive_starts(std::size_t count, std::uint32_t step = 1) {
  std::vector<std::uint32_t> s;
  for (std::uint32_t i = 0; i < count; ++i) s.push_back(i * step);
  return s;
}

inline Profile profile(std::vector<Point2> points) {
  return std::make_shared<const std::vector<ProfilePoint>>(std::move(points));
}

}  // namespace povtrace::test

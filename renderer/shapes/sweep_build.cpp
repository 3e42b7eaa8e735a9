// Builds lathe, prism and sor data from their descriptions as POV-Ray 3.7 does at parse time (source/backend/shape/
// lathe.cpp Compute_Lathe, prism.cpp Compute_Prism, sor.cpp Compute_Sor, 3.7-stable; read for the behaviour only):
// - A segment's x and y are cubics in w ∈ [0, 1] built from a window of points: linear (P0 → P1), quadratic (from P1
//   to P2, slope (P2 − P0)/2 at P1), cubic (Catmull-Rom from P1 to P2) or Bézier (P0 … P3; a prism's Bézier segment
//   runs backwards, from P3 at w = 0 to P0 at w = 1).
// - A segment's extent: its end points' coordinates (a Bézier segment: all four control points), plus for quadratic
//   and cubic segments the values where the derivative vanishes inside [0, 1].
// - A conic prism's rectangles are scaled by both heights. The sor's segment k is r² = a·y³ + b·y² + c·y + d through
//   points k+1 and k+2 with the slopes of r² there taken from the neighbouring points (2·r·Δr/Δy), solved through
//   the inverse of its 4×4 matrix by cofactors as POV-Ray does (so the coefficients round alike: the sor's
//   unpolished cubic makes the last bits visible); coefficients below 1e-10 become 0; its end discs' squared radii
//   come from the first and last segment, at least 0.
#include <algorithm>
#include <cmath>

#include "renderer/shapes/polynomial_roots.hpp"
#include "renderer/shapes/sweep.hpp"

namespace povtrace::render {

namespace {
constexpr double kEpsilon = tolerance::epsilon;

// Weights of the window's points in the coefficients c0 … c3 of each spline kind.
using Basis = std::array<std::array<double, 4>, 4>;
constexpr Basis linear_basis{{{0, 0, 0, 0}, {0, 0, 0, 0}, {-1, 1, 0, 0}, {1, 0, 0, 0}}};
constexpr Basis quadratic_basis{{{0, 0, 0, 0}, {0.5, -1, 0.5, 0}, {-0.5, 0, 0.5, 0}, {0, 1, 0, 0}}};
constexpr Basis catmull_rom_basis{{{-0.5, 1.5, -1.5, 0.5}, {1, -2.5, 2, -0.5}, {-0.5, 0, 0.5, 0}, {0, 1, 0, 0}}};
constexpr Basis bezier_basis{{{-1, 3, -3, 1}, {3, -6, 3, 0}, {-3, 3, 0, 0}, {1, 0, 0, 0}}};
constexpr Basis reversed_bezier_basis{{{1, -3, 3, -1}, {0, 3, -6, 3}, {0, 0, 3, -3}, {0, 0, 0, 1}}};

int window_size(SplineKind s) { return s == SplineKind::linear ? 2 : s == SplineKind::quadratic ? 3 : 4; }

ProfileSegment segment_from(const Basis& m, const ProfilePoint* window, int size) {
  ProfileSegment s;
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < size; ++j) {
      s.x[k] += m[k][j] * window[j][0];
      s.y[k] += m[k][j] * window[j][1];
    }
  return s;
}

ProfileSegment spline_segment(SplineKind spline, const ProfilePoint* window, bool reversed_bezier) {
  switch (spline) {
    case SplineKind::linear: return segment_from(linear_basis, window, 2);
    case SplineKind::quadratic: return segment_from(quadratic_basis, window, 3);
    case SplineKind::cubic: return segment_from(catmull_rom_basis, window, 4);
    case SplineKind::bezier: return segment_from(reversed_bezier ? reversed_bezier_basis : bezier_basis, window, 4);
  }
  return {};
}

struct Extent {
  double lo = tolerance::bound_huge, hi = -tolerance::bound_huge;
  void add(double v) { lo = std::min(lo, v); hi = std::max(hi, v); }
};

// The range of one coordinate over a segment (see the top of this file); `axis` 0 is x, 1 is y.
Extent coordinate_extent(SplineKind spline, const Cubic& c, const ProfilePoint* window, int axis) {
  Extent e;
  if (spline == SplineKind::bezier) {
    for (int j = 0; j < 4; ++j) e.add(window[j][axis]);
    return e;
  }
  const int from = spline == SplineKind::linear ? 0 : 1;
  e.add(window[from][axis]);
  e.add(window[from + 1][axis]);
  if (spline == SplineKind::linear) return e;
  const double slope[3] = {3.0 * c[0], 2.0 * c[1], c[2]};
  double roots[2];
  const int n = poly::solve_polynomial(2, slope, roots, false, 0.0, tolerance::max_distance);
  for (int k = 0; k < n; ++k)
    if (roots[k] >= 0.0 && roots[k] <= 1.0) e.add(evaluate(c, roots[k]));
  return e;
}

// The four products of a range with the two heights: a conic prism's rectangle side.
Extent scaled_by_heights(double lo, double hi, double h1, double h2) {
  Extent e;
  for (double v : {lo * h1, lo * h2, hi * h1, hi * h2}) e.add(v);
  return e;
}
}  // namespace

std::shared_ptr<LatheData> lathe_data(const Lathe& l) {
  auto d = std::make_shared<LatheData>();
  d->spline = l.spline;
  d->sturm = l.sturm;
  const auto& p = *l.points;
  const long n = static_cast<long>(p.size());
  const long count = l.spline == SplineKind::bezier ? n / 4 : n - window_size(l.spline) + 1;
  Extent r, h;
  for (long k = 0; k < count; ++k) {
    const ProfilePoint* window = &p[static_cast<std::size_t>(l.spline == SplineKind::bezier ? 4 * k : k)];
    const ProfileSegment s = spline_segment(l.spline, window, false);
    const Extent x = coordinate_extent(l.spline, s.x, window, 0), y = coordinate_extent(l.spline, s.y, window, 1);
    d->segments.push_back(s);
    d->rings.push_back(Ring{x.lo, x.hi, y.lo, y.hi});
    r.add(x.lo), r.add(x.hi), h.add(y.lo), h.add(y.hi);
  }
  d->radius1 = r.lo, d->radius2 = r.hi, d->height1 = h.lo, d->height2 = h.hi;
  return d;
}

std::shared_ptr<PrismData> prism_data(const Prism& pr) {
  auto d = std::make_shared<PrismData>();
  d->spline = pr.spline;
  d->conic = pr.conic;
  d->closed = !pr.open;
  d->sturm = pr.sturm;
  d->degenerate = pr.degenerate;
  d->height1 = pr.height1;
  d->height2 = pr.height2;
  Extent u, v;
  for (const std::uint32_t start : *pr.segment_starts) {
    const ProfilePoint* window = &(*pr.points)[start];
    PrismSegment s;
    s.curve = spline_segment(pr.spline, window, true);
    const Extent x = coordinate_extent(pr.spline, s.curve.x, window, 0);
    const Extent z = coordinate_extent(pr.spline, s.curve.y, window, 1);
    s.x1 = x.lo, s.x2 = s.u2 = x.hi, s.z1 = s.v1 = z.lo, s.z2 = s.v2 = z.hi;
    u.add(x.lo), u.add(x.hi), v.add(z.lo), v.add(z.hi);
    d->segments.push_back(s);
  }
  d->x1 = d->u1 = u.lo, d->x2 = d->u2 = u.hi, d->z1 = d->v1 = v.lo, d->z2 = d->v2 = v.hi;
  if (!pr.conic) return d;
  for (auto& s : d->segments) {
    const Extent x = scaled_by_heights(s.x1, s.x2, pr.height1, pr.height2);
    const Extent z = scaled_by_heights(s.z1, s.z2, pr.height1, pr.height2);
    s.x1 = x.lo, s.x2 = x.hi, s.z1 = z.lo, s.z2 = z.hi;
  }
  const Extent x = scaled_by_heights(d->x1, d->x2, pr.height1, pr.height2);
  const Extent z = scaled_by_heights(d->z1, d->z2, pr.height1, pr.height2);
  d->x1 = x.lo, d->x2 = x.hi, d->z1 = z.lo, d->z2 = z.hi;
  return d;
}

namespace {
using Matrix4 = std::array<std::array<double, 4>, 4>;

// The determinant of the 3×3 minor of m without row `skip_row` and column `skip_col`, by the rule of Sarrus.
double minor3(const Matrix4& m, int skip_row, int skip_col) {
  double a[3][3];
  for (int i = 0, r = 0; i < 4; ++i) {
    if (i == skip_row) continue;
    for (int j = 0, c = 0; j < 4; ++j)
      if (j != skip_col) a[r][c++] = m[i][j];
    ++r;
  }
  return a[0][0] * a[1][1] * a[2][2] + a[0][1] * a[1][2] * a[2][0] + a[0][2] * a[1][0] * a[2][1] -
         a[2][0] * a[1][1] * a[0][2] - a[2][1] * a[1][2] * a[0][0] - a[2][2] * a[1][0] * a[0][1];
}

// m⁻¹ by cofactors over the determinant (POV-Ray inverts the sor's matrix so, matrices.cpp MInvers).
Matrix4 inverse4(const Matrix4& m) {
  Matrix4 cof{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) cof[i][j] = minor3(m, i, j);
  const double det = m[0][0] * cof[0][0] - m[0][1] * cof[0][1] + m[0][2] * cof[0][2] - m[0][3] * cof[0][3];
  Matrix4 r{};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) r[i][j] = ((i + j) % 2 ? -cof[j][i] : cof[j][i]) / det;
  return r;
}

// Solves m·c = rhs: c = m⁻¹·rhs, each coefficient summed over rhs in order.
std::array<double, 4> solve_4x4(const Matrix4& m, const std::array<double, 4>& rhs) {
  const Matrix4 inv = inverse4(m);
  std::array<double, 4> c{};
  for (int i = 0; i < 4; ++i) c[i] = rhs[0] * inv[i][0] + rhs[1] * inv[i][1] + rhs[2] * inv[i][2] + rhs[3] * inv[i][3];
  return c;
}

double sor_radius2(const SorSegment& s, double y) { return ((s.a * y + s.b) * y + s.c) * y + s.d; }

// The cubic r²(y) through window points 1 and 2 with the slopes of r² the neighbours give.
SorSegment sor_segment(const ProfilePoint* p) {
  double slope1 = (p[2][0] - p[0][0]) / (p[2][1] - p[0][1]);
  double slope2 = (p[3][0] - p[1][0]) / (p[3][1] - p[1][1]);
  slope1 *= 2.0 * p[1][0];
  slope2 *= 2.0 * p[2][0];
  const double y1 = p[1][1], y2 = p[2][1];
  const auto c = solve_4x4({{{y1 * y1 * y1, y1 * y1, y1, 1.0},
                             {y2 * y2 * y2, y2 * y2, y2, 1.0},
                             {3.0 * y1 * y1, 2.0 * y1, 1.0, 0.0},
                             {3.0 * y2 * y2, 2.0 * y2, 1.0, 0.0}}},
                           {p[1][0] * p[1][0], p[2][0] * p[2][0], slope1, slope2});
  auto snap = [](double v) { return std::fabs(v) < kEpsilon ? 0.0 : v; };
  return SorSegment{snap(c[0]), snap(c[1]), snap(c[2]), snap(c[3])};
}

// The radius range of a sor segment: its end radii, and √r² where r² has a turning point between its heights
// (NaN where r² is negative there, kept as POV-Ray's min/max keep it).
Ring sor_ring(const SorSegment& s, const ProfilePoint* p) {
  double x[4] = {p[1][0], p[2][0], p[1][0], p[2][0]};
  const double y1 = p[1][1], y2 = p[2][1];
  const double slope[3] = {3.0 * s.a, 2.0 * s.b, s.c};
  double roots[2];
  const int n = poly::solve_polynomial(2, slope, roots, false, 0.0, tolerance::max_distance);
  for (int k = 0; k < n; ++k)
    if (roots[k] >= y1 && roots[k] <= y2) x[k] = std::sqrt(sor_radius2(s, roots[k]));
  return Ring{std::min(std::min(x[0], x[1]), std::min(x[2], x[3])),
              std::max(std::max(x[0], x[1]), std::max(x[2], x[3])), y1, y2};
}
}  // namespace

std::shared_ptr<SorData> sor_data(const Sor& so) {
  auto d = std::make_shared<SorData>();
  d->closed = !so.open;
  d->sturm = so.sturm;
  const auto& p = *so.points;
  Extent r, h;
  for (std::size_t k = 0; k + 3 < p.size(); ++k) {
    d->segments.push_back(sor_segment(&p[k]));
    d->rings.push_back(sor_ring(d->segments.back(), &p[k]));
    r.add(d->rings.back().r1), r.add(d->rings.back().r2), h.add(d->rings.back().h1), h.add(d->rings.back().h2);
  }
  d->radius2 = r.hi, d->height1 = h.lo, d->height2 = h.hi;
  auto at_least_zero = [](double v) { return v < 0.0 ? 0.0 : v; };
  d->cap_radius2 = at_least_zero(sor_radius2(d->segments.back(), d->rings.back().h2));
  d->base_radius2 = at_least_zero(sor_radius2(d->segments.front(), d->rings.front().h1));
  return d;
}

}  // namespace povtrace::render

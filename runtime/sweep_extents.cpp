// Profile segments and their ranges for lathe, prism and sor (see sweep_extents.hpp for what POV-Ray computes).
#include "runtime/sweep_extents.hpp"

#include <cmath>
#include <cstddef>
#include <utility>

#include "runtime/quadratic_roots.hpp"

namespace povtrace {

namespace {
constexpr double kEpsilon = 1e-10;       // POV-Ray's EPSILON: smaller sor coefficients are taken as 0
constexpr double kSmallEnough = 1e-10;   // SMALL_ENOUGH: Solve_Polynomial drops leading coefficients this small

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

// The roots of slope[0]·t² + slope[1]·t + slope[2] as POV-Ray's Solve_Polynomial(2, …) finds the turning points of a
// profile: leading coefficients below SMALL_ENOUGH are dropped first (a linear equation then has one root, a
// constant none), and two roots come larger first, as its solve_quadratic returns them. The order decides which
// candidate a sor's NaN radius replaces (sor_radius_range).
int turning_points(const double slope[3], double roots[2]) {
  int first = 0;
  while (first < 2 && std::fabs(slope[first]) < kSmallEnough) ++first;
  if (first == 2) return 0;
  if (first == 1) {
    roots[0] = -slope[2] / slope[1];
    return 1;
  }
  const int n = quadratic_roots(slope, roots);
  if (n == 2 && roots[0] < roots[1]) std::swap(roots[0], roots[1]);
  return n;
}

// The range of one coordinate over a lathe or prism segment (see sweep_extents.hpp); `axis` 0 is x, 1 is y.
ValueRange coordinate_range(SplineKind spline, const Cubic& c, const ProfilePoint* window, int axis) {
  ValueRange r;
  if (spline == SplineKind::bezier) {
    for (int j = 0; j < 4; ++j) r.add(window[j][axis]);
    return r;
  }
  const int from = spline == SplineKind::linear ? 0 : 1;
  r.add(window[from][axis]);
  r.add(window[from + 1][axis]);
  if (spline == SplineKind::linear) return r;
  const double slope[3] = {3.0 * c[0], 2.0 * c[1], c[2]};
  double roots[2];
  const int n = turning_points(slope, roots);
  for (int k = 0; k < n; ++k)
    if (roots[k] >= 0.0 && roots[k] <= 1.0) r.add(evaluate(c, roots[k]));
  return r;
}

BoundedSegment bounded_segment(SplineKind spline, const ProfilePoint* window, bool reversed_bezier) {
  const ProfileSegment curve = spline_segment(spline, window, reversed_bezier);
  return {curve, coordinate_range(spline, curve.x, window, 0), coordinate_range(spline, curve.y, window, 1)};
}

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

// m⁻¹ by cofactors over the determinant, as POV-Ray inverts the sor's matrix (matrices.cpp MInvers), so that the
// coefficients round alike: the renderer's unpolished cubic of a sor makes their last bits visible.
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

// The cubic r²(y) through window points 1 and 2 with the slopes of r² the neighbours give; coefficients below
// EPSILON in magnitude become 0, as in POV-Ray.
SorSegment sor_cubic(const ProfilePoint* p) {
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

// The radius range of a sor segment the way POV-Ray's Compute_Sor takes it: four candidates, the two end radii each
// twice, of which the k-th turning point of r² between the segment's heights replaces the k-th; then the min and
// max of the four as std::min and std::max pair them. Where r² is negative at a turning point its root is NaN, and
// the NaN is kept or lost by that pairing exactly as in POV-Ray: in the first candidate it makes both ends NaN (and
// such a range then drops out of the whole sor's), in the second it is passed over.
ValueRange sor_radius_range(const SorSegment& s, const ProfilePoint* p) {
  double x[4] = {p[1][0], p[2][0], p[1][0], p[2][0]};
  const double y1 = p[1][1], y2 = p[2][1];
  const double slope[3] = {3.0 * s.a, 2.0 * s.b, s.c};
  double roots[2];
  const int n = turning_points(slope, roots);
  for (int k = 0; k < n; ++k)
    if (roots[k] >= y1 && roots[k] <= y2) x[k] = std::sqrt(radius_squared(s, roots[k]));
  return ValueRange{std::min(std::min(x[0], x[1]), std::min(x[2], x[3])),
                    std::max(std::max(x[0], x[1]), std::max(x[2], x[3]))};
}

// Make_BBox of a shape turned about the y axis: the square of half side `radius` between the heights.
ExtentBox radial_box(double radius, const ValueRange& height) {
  return ExtentBox::make({-radius, height.lo, -radius}, {2.0 * radius, height.hi - height.lo, 2.0 * radius});
}
}  // namespace

ProfileRanges profile_ranges(const std::vector<BoundedSegment>& segments) {
  ProfileRanges r;
  for (const BoundedSegment& s : segments) {
    r.x.add(s.x);
    r.y.add(s.y);
  }
  return r;
}

std::vector<BoundedSegment> lathe_segments(const Lathe& lathe) {
  const auto& p = *lathe.points;
  const bool bezier = lathe.spline == SplineKind::bezier;
  const long n = static_cast<long>(p.size());
  const long count = bezier ? n / 4 : n - window_size(lathe.spline) + 1;
  std::vector<BoundedSegment> segments;
  for (long k = 0; k < count; ++k)
    segments.push_back(bounded_segment(lathe.spline, &p[static_cast<std::size_t>(bezier ? 4 * k : k)], false));
  return segments;
}

std::vector<BoundedSegment> prism_segments(const Prism& prism) {
  std::vector<BoundedSegment> segments;
  for (const std::uint32_t start : *prism.segment_starts)
    segments.push_back(bounded_segment(prism.spline, &(*prism.points)[start], true));
  return segments;
}

ValueRange scaled_by_heights(const ValueRange& r, double height1, double height2) {
  ValueRange scaled;
  for (double v : {r.lo * height1, r.lo * height2, r.hi * height1, r.hi * height2}) scaled.add(v);
  return scaled;
}

ProfileRanges prism_rectangle(const Prism& prism, const ProfileRanges& outline) {
  if (!prism.conic) return outline;
  return {scaled_by_heights(outline.x, prism.height1, prism.height2),
          scaled_by_heights(outline.y, prism.height1, prism.height2)};
}

std::vector<BoundedSorSegment> sor_segments(const Sor& sor) {
  const auto& p = *sor.points;
  std::vector<BoundedSorSegment> segments;
  for (std::size_t k = 0; k + 3 < p.size(); ++k) {
    const SorSegment cubic = sor_cubic(&p[k]);
    segments.push_back({cubic, sor_radius_range(cubic, &p[k]), ValueRange{p[k + 1][1], p[k + 2][1]}});
  }
  return segments;
}

ProfileRanges sor_ranges(const std::vector<BoundedSorSegment>& segments) {
  ProfileRanges r;
  for (const BoundedSorSegment& s : segments) {
    r.x.add(s.radius);
    r.y.add(s.height);
  }
  return r;
}

// Lathe::Compute_BBox and Sor::Compute_BBox use only the largest radius (a lathe's radii may be negative: POV-Ray
// squares them when intersecting, but its box takes the largest signed value).
ExtentBox lathe_local_box(const Lathe& lathe) {
  const ProfileRanges r = profile_ranges(lathe_segments(lathe));
  return radial_box(r.x.hi, r.y);
}

ExtentBox sor_local_box(const Sor& sor) {
  const ProfileRanges r = sor_ranges(sor_segments(sor));
  return radial_box(r.x.hi, r.y);
}

// Prism::Compute_BBox: the rectangle from the lower corner, between the two heights.
ExtentBox prism_local_box(const Prism& prism) {
  const ProfileRanges r = prism_rectangle(prism, profile_ranges(prism_segments(prism)));
  return ExtentBox::make({r.x.lo, prism.height1, r.y.lo},
                         {r.x.hi - r.x.lo, prism.height2 - prism.height1, r.y.hi - r.y.lo});
}

}  // namespace povtrace

// The 2-D geometry of a glyph outline shared by inside() and the renderer: POV-Ray's point-in-glyph test and its
// quadratic solver (source/backend/shape/truetype.cpp Inside_Glyph, solve_quad, 3.7-stable). Facts reproduced:
// - The outline is walked contour by contour into straight edges and quadratic pieces (glyph_contour_walk.hpp).
// - Straight edges: horizontal ones never cross; an edge crosses when its ends lie on opposite sides of y (a side
//   is "below": strictly less than y), and either both ends are right of x (strictly greater), or one is and the
//   crossing's x, found through the edge's slope, is right of x minus 1e-10.
// - Quadratic pieces are skipped when all three points are strictly below or strictly above y. Otherwise the
//   roots in [0, 1] of y(s) = y count, except a root within 1e-10 of an end whose y range (with the control
//   point) does not really reach y there; each remaining root crosses when its x is strictly right of x.
// - The point is inside for an odd number of crossings.
#include <cmath>

#include "runtime/glyph_contour_walk.hpp"
#include "scene/text_description.hpp"

namespace povtrace {

namespace {
constexpr double kEpsilon = 1e-10;       // POV-Ray's EPSILON
constexpr double kCoeffLimit = 1e-20;    // truetype.cpp COEFF_LIMIT: a smaller leading coefficient is zero

bool in_unit(double s) { return s >= 0.0 && s <= 1.0; }

// A straight edge (x0, y0) → (x1, y1) and the ray from (x, y) towards +x.
bool edge_crosses(double x0, double y0, double x1, double y1, double x, double y) {
  if (y0 == y1) return false;
  if ((y0 < y) == (y1 < y)) return false;
  const bool right0 = x0 > x, right1 = x1 > x;
  if (right0 && right1) return true;
  if (!right0 && !right1) return false;
  const double slope = (y1 - y0) / (x1 - x0);
  const double offset = (y1 - y) - slope * (x1 - x);
  return offset / slope < kEpsilon;
}

// Drops root k (shifting the next one down), as POV-Ray's filter does.
void drop_root(double roots[2], int& count, int k) {
  --count;
  if (count > k) roots[k] = roots[k + 1];
}

// The crossings of the quadratic piece (x0, y0), control (x1, y1), end (x2, y2) with the ray from (x, y).
int curve_crossings(const double px[3], const double py[3], double x, double y) {
  if ((py[0] < y && py[1] < y && py[2] < y) || (py[0] > y && py[1] > y && py[2] > y)) return 0;
  const double c[3] = {py[0] - 2.0 * py[1] + py[2], 2.0 * (py[1] - py[0]), py[0] - y};
  double roots[2];
  int count = solve_glyph_quadratic(c, roots);
  for (int k = 0; k < count;) {
    const bool near_start = roots[k] <= kEpsilon, near_end = !near_start && roots[k] >= 1.0 - kEpsilon;
    const bool start_misses = (y <= py[0] && y < py[1]) || (y >= py[0] && y > py[1]);
    const bool end_misses = (y < py[2] && y < py[1]) || (y > py[2] && y > py[1]);
    if ((near_start && start_misses) || (near_end && end_misses)) drop_root(roots, count, k);
    else ++k;
  }
  const double a = px[0] - 2.0 * px[1] + px[2], b = 2.0 * (px[1] - px[0]);
  int crossings = 0;
  for (int k = 0; k < count; ++k)
    if ((a * roots[k] + b) * roots[k] + px[0] > x) ++crossings;
  return crossings;
}

int contour_crossings(const GlyphContour& c, double x, double y) {
  int crossings = 0;
  walk_glyph_contour(
      c,
      [&](double x0, double y0, double x1, double y1) {
        if (edge_crosses(x0, y0, x1, y1, x, y)) ++crossings;
      },
      [&](const double px[3], const double py[3]) { crossings += curve_crossings(px, py, x, y); });
  return crossings;
}
}  // namespace

int solve_glyph_quadratic(const double c[3], double roots[2]) {
  const double a = c[0], b = -c[1], k = c[2];
  if (std::fabs(a) < kCoeffLimit) {
    if (std::fabs(b) < kCoeffLimit) return 0;
    const double s = k / b;
    if (!in_unit(s)) return 0;
    roots[0] = s;
    return 1;
  }
  double d = b * b - 4.0 * a * k;
  if (d < kEpsilon) return 0;
  d = std::sqrt(d);
  const double two_a = 2.0 * a;
  const double first = (b + d) / two_a, second = (b - d) / two_a;
  int count = 0;
  if (in_unit(first)) roots[count++] = first;
  if (in_unit(second)) roots[count++] = second;
  return count;
}

bool inside_glyph(const GlyphOutline& glyph, double x, double y) {
  int crossings = 0;
  for (const GlyphContour& c : glyph.contours) crossings += contour_crossings(c, x, y);
  return (crossings & 1) != 0;
}

}  // namespace povtrace

// The walk along one glyph contour that POV-Ray's text shape makes both for its inside test and for the ray's wall
// hits (source/backend/shape/truetype.cpp Inside_Glyph and GlyphIntersect, 3.7-stable): one walker for
// inside_glyph (glyph_outline.cpp) and the text shape's walls (renderer/shapes/text.cpp), so the two always cut a
// contour into the same pieces.
// - The contour starts at its first point, which is taken as on the curve whatever its flag says.
// - An on-curve point ends a straight edge from the previous end.
// - An off-curve point is the control point of a quadratic piece that ends at the next point if that one is on the
//   curve, half way to it if it is off the curve, or at the first point for the last point of the contour.
#pragma once

#include <cstddef>

#include "scene/text_description.hpp"

namespace povtrace {

// Calls edge(x0, y0, x1, y1) for every straight edge and curve(px, py) (start, control and end point coordinates,
// each `const double[3]`) for every quadratic piece of contour `c`, in contour order.
template <class OnEdge, class OnCurve>
void walk_glyph_contour(const GlyphContour& c, OnEdge&& edge, OnCurve&& curve) {
  const std::size_t n = c.count();
  if (n == 0) return;
  double x0 = c.x[0], y0 = c.y[0];
  for (std::size_t j = 1; j <= n; ++j) {
    if (c.on_curve[j]) {
      edge(x0, y0, c.x[j], c.y[j]);
      x0 = c.x[j];
      y0 = c.y[j];
      continue;
    }
    double x2 = c.x[0], y2 = c.y[0];
    if (j < n) {
      x2 = c.x[j + 1];
      y2 = c.y[j + 1];
      if (!c.on_curve[j + 1]) {
        x2 = 0.5 * (c.x[j] + x2);
        y2 = 0.5 * (c.y[j] + y2);
      }
    }
    const double px[3] = {x0, c.x[j], x2}, py[3] = {y0, c.y[j], y2};
    curve(px, py);
    x0 = x2;
    y0 = y2;
  }
}

}  // namespace povtrace

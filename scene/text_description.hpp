// Scene-description form of the text shape (povray-sdl-and-geometry.md §8, POV-Ray 3.7 reference "Text"):
// `text { ttf "font.ttf" "string" thickness, <offset> }`. Included by description.hpp.
//
// POV-Ray builds a text object as a union with one child per character (source/backend/shape/truetype.cpp
// ProcessNewTTF): each child is the character's glyph outline extruded from z = 0 to z = thickness and placed by a
// translation in the text's plane. The parser reads the font and lays the string out (parser/truetype*.cpp,
// runtime/text_layout.cpp) exactly as POV-Ray does; the renderer only intersects the extruded outlines.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "vecmath.hpp"

namespace povtrace {

// One closed contour of a glyph in em units (font units divided by unitsPerEm), as POV-Ray's
// ConvertOutlineToGlyph leaves it: the contour's points in file order with their on-curve flags, then the first
// point (and its flag) once more. Off-curve points are quadratic B-spline control points; two off-curve points in
// a row have an implied on-curve point half way between them.
struct GlyphContour {
  std::vector<double> x, y;             // size() = number of points + 1
  std::vector<std::uint8_t> on_curve;   // 1 = on the curve, 0 = a control point
  std::size_t count() const { return x.empty() ? 0 : x.size() - 1; }
};

// A glyph's outline plus the header box POV-Ray keeps for it (in font units, as 16-bit integers: xMin … yMax).
struct GlyphOutline {
  std::vector<GlyphContour> contours;
  int x_min = 0, y_min = 0, x_max = 0, y_max = 0;
  int units_per_em = 1;
};

// One character of a text object: its outline and where POV-Ray's layout puts it (a translation in the xy plane).
struct TextGlyph {
  std::shared_ptr<const GlyphOutline> outline;
  double x = 0, y = 0;
};

// text { … }: the laid-out glyphs, each extruded over 0 <= z <= thickness. POV-Ray makes a text a CSG union of its
// glyphs, so its bounding box is carried through each later transform (by the parser, in its notes on the object:
// parser/extents/object_notes.hpp), starting with the tiny anti-crack rotation.
struct Text {
  std::vector<TextGlyph> glyphs;
  double thickness = 1;
};

// POV-Ray's point-in-glyph test (TrueType::Inside_Glyph): the parity of the outline crossings of the ray from
// (x, y) towards +x, with its own tolerances. Used by inside() at parse time and by the renderer.
bool inside_glyph(const GlyphOutline& glyph, double x, double y);

// POV-Ray's quadratic solver of the text shape (TrueType::solve_quad): the roots s in [0, 1] of
// c[0]·s² + c[1]·s + c[2] = 0, in POV-Ray's order; returns how many (0, 1 or 2). A discriminant below 1e-10
// counts as no root, and |c[0]| < 1e-20 makes the equation linear.
int solve_glyph_quadratic(const double c[3], double roots[2]);

}  // namespace povtrace

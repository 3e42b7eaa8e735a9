// The renderer's form of a text object: its glyphs with POV-Ray's per-glyph box (TrueType::Compute_BBox).
#include "renderer/shapes/text.hpp"

namespace povtrace::render {

std::shared_ptr<TextData> text_data(const Text& text) {
  constexpr double text_depth = 1e-6;   // truetype.cpp TTF_Tolerance, also the box's margin in z
  auto d = std::make_shared<TextData>();
  d->thickness = text.thickness;
  for (const TextGlyph& g : text.glyphs) {
    const double funit = 1.0 / g.outline->units_per_em;
    d->glyphs.push_back(TextShapeGlyph{
        g.outline, g.x, g.y, Vec3{g.outline->x_min * funit, g.outline->y_min * funit, -text_depth},
        Vec3{g.outline->x_max * funit, g.outline->y_max * funit, text.thickness + text_depth}});
  }
  return d;
}

}  // namespace povtrace::render

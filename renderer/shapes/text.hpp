// A text object's glyphs as the renderer keeps them (text_build.cpp builds them, text.cpp intersects them).
#pragma once

#include <memory>
#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

struct TextShapeGlyph {
  std::shared_ptr<const GlyphOutline> outline;
  double x = 0, y = 0;   // the glyph's translation in the text's plane
  Vec3 lo, hi;           // POV-Ray's box of the glyph in its own (untranslated) space, z included
};

struct TextData : ShapeData {
  double thickness = 1;
  std::vector<TextShapeGlyph> glyphs;
};

std::shared_ptr<TextData> text_data(const Text& text);

// SurfaceHit::element of a text hit: which surface; a wall hit keeps its object-space normal in (u, v).
enum class TextSurface : std::uint32_t { wall = 0, front = 1, back = 2 };

}  // namespace povtrace::render

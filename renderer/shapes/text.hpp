// A text object's glyphs as the renderer keeps them (text_build.cpp builds them, text.cpp intersects them).
#pragma once

#include <memory>
#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/solid_shapes.hpp"

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

namespace povtrace::render::shapes {

// text (text.cpp, built by text_build.cpp): TextData in object space; any number of roots. A hit's element is the
// TextSurface, and on a wall u and v carry the normal's x and y.
struct TextShape {
  using Description = Text;
  static Primitive build(const Text& description, const Matrix& world_from_object) {
    return make_text(description, world_from_object);
  }
  static void collect(const Primitive& p, const Ray& ray, HitBuffer& out);   // appends every hit
  static std::optional<SurfaceHit> nearest(const Primitive& p, const Ray& ray, double t_min, double t_max);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

// Builds the primitives of solid_shapes.hpp from their descriptions.
#include "renderer/shapes/solid_shapes.hpp"

#include <stdexcept>

#include "renderer/shapes/blob.hpp"
#include "renderer/shapes/text.hpp"

namespace povtrace::render {

namespace {
Primitive placed(ShapeType type, const Matrix& world_from_object) {
  Primitive p;
  p.type = type;
  p.transformed = !(world_from_object == Matrix::identity());
  p.world_from_object = world_from_object;
  if (p.transformed) p.object_from_world = world_from_object.inverse();
  return p;
}
}  // namespace

// Parse_Superellipsoid stores the powers 2/e, e/n and 2/n.
Primitive make_superellipsoid(const Superellipsoid& s, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::superellipsoid, world_from_object);
  p.a = Vec3{2.0 / s.e, s.e / s.n, 2.0 / s.n};
  return p;
}

Primitive make_blob(const Blob& b, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::blob, world_from_object);
  p.data = blob_data(b);
  return p;
}

Primitive make_text(const Text& t, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::text, world_from_object);
  p.data = text_data(t);
  return p;
}

bool is_solid_shape(const Shape& shape) {
  return std::holds_alternative<Superellipsoid>(shape) || std::holds_alternative<HeightField>(shape) ||
         std::holds_alternative<Blob>(shape) || std::holds_alternative<Text>(shape);
}

Primitive solid_primitive(const Shape& shape, const Matrix& world_from_object) {
  if (const auto* s = std::get_if<Superellipsoid>(&shape)) return make_superellipsoid(*s, world_from_object);
  if (const auto* h = std::get_if<HeightField>(&shape)) return make_height_field(*h, world_from_object);
  if (const auto* b = std::get_if<Blob>(&shape)) return make_blob(*b, world_from_object);
  if (const auto* t = std::get_if<Text>(&shape)) return make_text(*t, world_from_object);
  throw std::logic_error("solid_primitive of a shape that is not one of solid_shapes.hpp");
}

}  // namespace povtrace::render

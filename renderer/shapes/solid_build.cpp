// Builds the primitives of solid_shapes.hpp from their descriptions.
#include "renderer/shapes/solid_shapes.hpp"

#include <stdexcept>

#include "renderer/shapes/blob.hpp"
#include "renderer/shapes/text.hpp"
#include "renderer/shapes/isosurface.hpp"
#include "renderer/shapes/sweep.hpp"

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

Primitive make_lathe(const Lathe& l, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::lathe, world_from_object);
  p.data = lathe_data(l);
  return p;
}

Primitive make_prism(const Prism& pr, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::prism, world_from_object);
  p.data = prism_data(pr);
  return p;
}

Primitive make_sor(const Sor& s, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::sor, world_from_object);
  p.data = sor_data(s);
  return p;
}

std::shared_ptr<IsosurfaceData> isosurface_data(const Isosurface& iso) {
  auto d = std::make_shared<IsosurfaceData>();
  d->function = iso.function;
  d->sphere_container = iso.sphere_container;
  d->corner1 = iso.corner1;
  d->corner2 = iso.corner2;
  d->centre = iso.centre;
  d->radius = iso.radius;
  d->threshold = iso.threshold;
  d->accuracy = iso.accuracy;
  d->max_gradient = iso.max_gradient;
  d->max_trace = iso.max_trace;
  d->closed = !iso.open;
  return d;
}

Primitive make_isosurface(const Isosurface& iso, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::isosurface, world_from_object);
  p.data = isosurface_data(iso);
  return p;
}

bool is_solid_shape(const Shape& shape) {
  return std::holds_alternative<Superellipsoid>(shape) || std::holds_alternative<HeightField>(shape) ||
         std::holds_alternative<Blob>(shape) || std::holds_alternative<Text>(shape) ||
         std::holds_alternative<Lathe>(shape) ||
         std::holds_alternative<Prism>(shape) || std::holds_alternative<Sor>(shape) ||
         std::holds_alternative<Isosurface>(shape);
}

Primitive solid_primitive(const Shape& shape, const Matrix& world_from_object) {
  if (const auto* s = std::get_if<Superellipsoid>(&shape)) return make_superellipsoid(*s, world_from_object);
  if (const auto* h = std::get_if<HeightField>(&shape)) return make_height_field(*h, world_from_object);
  if (const auto* b = std::get_if<Blob>(&shape)) return make_blob(*b, world_from_object);
  if (const auto* t = std::get_if<Text>(&shape)) return make_text(*t, world_from_object);
  if (const auto* l = std::get_if<Lathe>(&shape)) return make_lathe(*l, world_from_object);
  if (const auto* p = std::get_if<Prism>(&shape)) return make_prism(*p, world_from_object);
  if (const auto* s = std::get_if<Sor>(&shape)) return make_sor(*s, world_from_object);
  if (const auto* iso = std::get_if<Isosurface>(&shape)) return make_isosurface(*iso, world_from_object);
  throw std::logic_error("solid_primitive of a shape that is not one of solid_shapes.hpp");
}

}  // namespace povtrace::render

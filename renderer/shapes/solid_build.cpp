// Builds the primitives of solid_shapes.hpp from their descriptions.
#include "renderer/shapes/solid_shapes.hpp"

#include "renderer/shapes/blob.hpp"
#include "renderer/shapes/text.hpp"
#include "renderer/shapes/isosurface.hpp"
#include "renderer/shapes/sweep.hpp"

namespace povtrace::render {

// Parse_Superellipsoid stores the powers 2/e, e/n and 2/n.
Primitive make_superellipsoid(const Superellipsoid& s, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::superellipsoid, world_from_object);
  p.a = Vec3{2.0 / s.e, s.e / s.n, 2.0 / s.n};
  return p;
}

Primitive make_blob(const Blob& b, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::blob, world_from_object);
  p.data = blob_data(b);
  return p;
}

Primitive make_text(const Text& t, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::text, world_from_object);
  p.data = text_data(t);
  return p;
}

Primitive make_lathe(const Lathe& l, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::lathe, world_from_object);
  p.data = lathe_data(l);
  return p;
}

Primitive make_prism(const Prism& pr, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::prism, world_from_object);
  p.data = prism_data(pr);
  return p;
}

Primitive make_sor(const Sor& s, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::sor, world_from_object);
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
  d->evaluate = iso.evaluate;
  d->evaluate_params = iso.evaluate_params;
  d->max_trace = iso.max_trace;
  d->closed = !iso.open;
  return d;
}

Primitive make_isosurface(const Isosurface& iso, const Matrix& world_from_object) {
  Primitive p = placed_primitive(ShapeType::isosurface, world_from_object);
  std::shared_ptr<IsosurfaceData> data = isosurface_data(iso);
  learn_evaluate_gradient(*data);
  p.data = std::move(data);
  return p;
}

Primitive shapes::IsosurfaceShape::build(const Isosurface& iso, const Matrix& world_from_object,
                                         const BuildContext& context) {
  Primitive p = placed_primitive(ShapeType::isosurface, world_from_object);
  std::shared_ptr<IsosurfaceData> data = isosurface_data(iso);
  data->noise_generator = context.noise_generator;
  learn_evaluate_gradient(*data);
  p.data = std::move(data);
  return p;
}

}  // namespace povtrace::render

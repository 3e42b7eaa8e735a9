#include "renderer/object_primitives.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "runtime/image_files.hpp"
#include "renderer/csg_build.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/tracer.hpp"
#include "renderer/shapes/isosurface.hpp"
#include "renderer/shapes/poly_shape.hpp"
#include "renderer/shapes/quadric_shapes.hpp"
#include "renderer/shapes/solid_shapes.hpp"
#include "renderer/shapes/triangle_shapes.hpp"

namespace povtrace::render {

namespace {
// A height field made from a pigment function (`function W, H { pigment { … } }`): POV-Ray's Make_Pattern_Image
// stores the pigment's colour at (j / (W − 1), i / (H − 1), 0) in a 16-bit RGBA image (each channel as
// sdl::function_image_value keeps it), and image_height_at reads a 16-bit colour image as its grey
// 0.297 r + 0.589 g + 0.114 b, · 65535, truncated. The image's bottom row is the height field's z = 0.

// The pigment's patterns use the generator in force when the height field was parsed (POV-Ray samples it then),
// functions in it the scene's (`scene_generator`).
Shape with_pigment_samples(const Shape& shape, int scene_generator) {
  const auto* h = std::get_if<HeightField>(&shape);
  if (!h || !h->pigment_function) return shape;
  RenderPigment pigment = build_render_pigment(*h->pigment_function);
  set_generator(pigment, static_cast<NoiseGenerator>(h->noise_generator));
  set_function_generator(pigment, scene_generator);
  const int w = h->samples_width, d = h->samples_depth;
  auto samples = std::make_shared<std::vector<std::uint16_t>>(static_cast<std::size_t>(w) * d);
  for (int i = 0; i < d; ++i)
    for (int j = 0; j < w; ++j) {
      const Vec3 p{static_cast<double>(j) / (w - 1), static_cast<double>(i) / (d - 1), 0.0};
      const Colour c = evaluate_pigment(pigment, p);
      const double grey = 0.297 * sdl::function_image_value(c.r) + 0.589 * sdl::function_image_value(c.g) +
                          0.114 * sdl::function_image_value(c.b);
      (*samples)[static_cast<std::size_t>(d - 1 - i) * w + j] = static_cast<std::uint16_t>(grey * 65535.0f);
    }
  HeightField sampled = *h;
  sampled.samples = std::move(samples);
  return sampled;
}

// An isosurface's data with the scene's noise generator, which its function reads.
std::shared_ptr<const ShapeData> with_noise_generator(const std::shared_ptr<const ShapeData>& data, int generator) {
  auto iso = std::make_shared<IsosurfaceData>(static_cast<const IsosurfaceData&>(*data));
  iso->noise_generator = generator;
  return iso;
}
}  // namespace

void add_shape_primitives(const Object& o, std::uint32_t material, std::uint32_t object_index,
                          const BuildContext& context, std::vector<Primitive>& out) {
  Primitive p;
  p.material = material;
  p.object = object_index;
  p.casts_shadow = !o.no_shadow;
  set_ray_flags(p, o);
  p.inverse = o.inverse;
  p.transformed = !(o.world_from_object == Matrix::identity());
  p.world_from_object = o.world_from_object;
  if (p.transformed) p.object_from_world = o.world_from_object.inverse();
  if (const auto* s = std::get_if<Sphere>(&o.shape)) {
    p.type = ShapeType::sphere;
    p.a = s->centre;
    p.radius = s->radius;
  } else if (const auto* pl = std::get_if<Plane>(&o.shape)) {
    p.type = ShapeType::plane;
    p.a = pl->normal;
    p.radius = pl->distance;
  } else if (const auto* b = std::get_if<Box>(&o.shape)) {
    p.type = ShapeType::box;
    p.a = b->corner1;
    p.b = b->corner2;
  } else if (is_quadric_shape(o.shape)) {
    const std::optional<Primitive> shape = quadric_primitive(o.shape, o.world_from_object);
    if (!shape) return;   // a disc with a zero normal: POV-Ray renders nothing either
    p.type = shape->type;
    p.a = shape->a;
    p.b = shape->b;
    p.radius = shape->radius;
    p.transformed = shape->transformed;
    p.world_from_object = shape->world_from_object;
    p.object_from_world = shape->object_from_world;
  } else if (const auto* quadric = std::get_if<Quadric>(&o.shape)) {
    // Kept in world space, as POV-Ray keeps it: the transforms are in the coefficients.
    const Primitive shape = make_quadric(*quadric, o.world_from_object);
    p.type = shape.type;
    p.data = shape.data;
    p.transformed = false;
    p.world_from_object = Matrix::identity();
  } else if (const auto* polynomial = std::get_if<Poly>(&o.shape)) {
    const Primitive shape = make_poly(*polynomial, o.world_from_object);
    p.type = shape.type;
    p.data = shape.data;
  } else if (const auto* tri = std::get_if<Triangle>(&o.shape)) {
    p.type = ShapeType::triangle;
    shapes::set_up_triangle(p, *tri);
  } else if (const auto* poly = std::get_if<Polygon>(&o.shape)) {
    p.type = ShapeType::polygon;
    shapes::set_up_polygon(p, *poly);
  } else if (const auto* mesh = std::get_if<Mesh>(&o.shape)) {
    p.type = ShapeType::mesh;
    shapes::set_up_mesh(p, context.meshes.shape_for(mesh->data));
  } else if (is_solid_shape(o.shape)) {
    const Primitive shape =
        solid_primitive(with_pigment_samples(o.shape, context.noise_generator), o.world_from_object);
    p.type = shape.type;
    p.a = shape.a;
    p.b = shape.b;
    p.radius = shape.radius;
    p.data = std::holds_alternative<Isosurface>(o.shape) ? with_noise_generator(shape.data, context.noise_generator)
                                                         : shape.data;
    p.transformed = shape.transformed;
    p.world_from_object = shape.world_from_object;
    p.object_from_world = shape.object_from_world;
  } else {
    throw std::logic_error("CSG objects become CSG nodes in add_object and never reach add_primitives");
  }
  out.push_back(p);
}

}  // namespace povtrace::render

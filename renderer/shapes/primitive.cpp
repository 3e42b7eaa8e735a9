// geometry.hpp's per-shape functions: each one switch over the registered shapes (shape_registry.hpp), calling the
// shape's own struct. Each shape applies its own transform because POV-Ray applies the depth tolerances in
// different spaces per shape (see the header comment of each shape file). Also the two non-inline Bounds members
// and the build of a shape from its description.
#include <cmath>
#include <optional>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "renderer/geometry.hpp"
#include "renderer/shapes/shape_registry.hpp"

namespace povtrace::render {

bool Bounds::finite() const {
  for (int i = 0; i < 3; ++i)
    if (!std::isfinite(lo[i]) || !std::isfinite(hi[i])) return false;
  return !empty();
}

double Bounds::surface_area() const {
  if (empty()) return 0.0;
  const Vec3 e = hi - lo;
  return 2.0 * (e.x * e.y + e.y * e.z + e.z * e.x);
}

Vec3 hit_point(const Ray& ray, const SurfaceHit& hit) {
  return shapes::visit_shape(hit.leaf->type,
                             [&]<class S>(std::type_identity<S>) { return shapes::hit_point_of<S>(ray, hit); });
}

Primitive placed_primitive(ShapeType type, const Matrix& world_from_object) {
  Primitive p;
  p.type = type;
  p.transformed = !(world_from_object == Matrix::identity());
  p.world_from_object = world_from_object;
  if (p.transformed) p.object_from_world = world_from_object.inverse();
  return p;
}

Intersections intersect_all(const Primitive& p, const Ray& ray) {
  return shapes::visit_shape(p.type, [&]<class S>(std::type_identity<S>) { return shapes::intersections_of<S>(p, ray); });
}

void collect_hits(const Primitive& p, const Ray& ray, HitBuffer& out) {
  shapes::visit_shape(p.type, [&]<class S>(std::type_identity<S>) { shapes::collect_hits_of<S>(p, ray, out); });
}

std::optional<SurfaceHit> nearest_hit(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  return shapes::visit_shape(
      p.type, [&]<class S>(std::type_identity<S>) { return shapes::nearest_hit_of<S>(p, ray, t_min, t_max); });
}

Vec3 surface_normal(const SurfaceHit& hit, Vec3 world_point) {
  return shapes::visit_shape(
      hit.leaf->type, [&]<class S>(std::type_identity<S>) { return shapes::hit_normal_of<S>(hit, world_point); });
}

Vec3 surface_normal(const Primitive& p, Vec3 world_point) {
  return shapes::visit_shape(p.type, [&]<class S>(std::type_identity<S>) { return S::normal(p, world_point); });
}

bool inside(const Primitive& p, Vec3 world_point) {
  return shapes::visit_shape(p.type, [&]<class S>(std::type_identity<S>) { return shapes::inside_of<S>(p, world_point); });
}

Bounds world_bounds(const Primitive& p) {
  return shapes::visit_shape(p.type, [&]<class S>(std::type_identity<S>) { return shapes::world_bounds_of<S>(p); });
}

std::array<double, 2> uv_coordinates(const SurfaceHit& hit, Vec3 world_point, double scene_scale) {
  return shapes::visit_shape(hit.leaf->type, [&]<class S>(std::type_identity<S>) {
    return shapes::uv_of<S>(hit, world_point, scene_scale);
  });
}

namespace shapes {

namespace {
template <class S>
Primitive* append_from(const typename S::Description& description, const Matrix& world_from_object,
                       const BuildContext& context, std::vector<Primitive>& out) {
  if constexpr (!HasContextBuild<S> && !HasBuild<S>) {
    throw std::logic_error("CSG objects become CSG nodes in add_object and never reach add_shape_primitives");
  } else {
    const auto build = [&] {
      if constexpr (HasContextBuild<S>) return S::build(description, world_from_object, context);
      else return S::build(description, world_from_object);
    };
    if constexpr (std::is_same_v<decltype(build()), std::optional<Primitive>>) {
      std::optional<Primitive> p = build();
      if (!p) return nullptr;
      return &out.emplace_back(std::move(*p));
    } else {
      return &out.emplace_back(build());
    }
  }
}
}  // namespace

Primitive* append_shape(const Shape& description, const Matrix& world_from_object, const BuildContext& context,
                        std::vector<Primitive>& out) {
  return std::visit(
      [&](const auto& d) -> Primitive* {
        using D = std::decay_t<decltype(d)>;
#define POVTRACE_SHAPE_BUILD(name, Shape)                        \
  if constexpr (std::is_same_v<D, typename Shape::Description>) \
    return append_from<Shape>(d, world_from_object, context, out); \
  else
        POVTRACE_SHAPES(POVTRACE_SHAPE_BUILD)
#undef POVTRACE_SHAPE_BUILD
        static_assert(sizeof(D) == 0, "a shape description that no registered shape builds");
      },
      description);
}

}  // namespace shapes

}  // namespace povtrace::render

// The poly behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/poly_shape.hpp"

namespace povtrace::render::shapes {

// poly (poly.cpp): PolyData in object space.
struct PolyShape {
  using Description = Poly;
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds world_bounds(const Primitive& p);
  static Primitive build(const Poly& description, const Matrix& world_from_object) {
    return make_poly(description, world_from_object);
  }
};

}  // namespace povtrace::render::shapes

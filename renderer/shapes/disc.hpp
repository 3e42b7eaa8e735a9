// The disc behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/quadric_shapes.hpp"

namespace povtrace::render::shapes {

// disc (disc.cpp): the canonical plane z = 0 of quadric_shapes.hpp.
struct DiscShape {
  using Description = Disc;
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  // Nothing for a zero normal: POV-Ray's NaN disc renders nothing.
  static std::optional<Primitive> build(const Disc& description, const Matrix& world_from_object) {
    if (description.normal == Vec3{}) return std::nullopt;
    return make_disc(description, world_from_object);
  }
};

}  // namespace povtrace::render::shapes

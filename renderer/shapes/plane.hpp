// The plane behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

// plane (plane.cpp): a = unit normal N, radius = distance d (the surface N·P = d); unbounded.
struct PlaneShape {
  using Description = Plane;
  static Primitive build(const Plane& description, const Matrix& world_from_object);
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds world_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

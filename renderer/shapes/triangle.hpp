// The triangle behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/triangle_shapes.hpp"

namespace povtrace::render::shapes {

// triangle and smooth_triangle (triangle.cpp): TriangleData in world space. Never inside, as in POV-Ray.
struct TriangleShape {
  using Description = Triangle;
  static Primitive build(const Triangle& description, const Matrix& world_from_object);
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static Bounds world_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

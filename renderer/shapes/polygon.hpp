// The polygon behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/triangle_shapes.hpp"

namespace povtrace::render::shapes {

// polygon (polygon.cpp): PolygonData in its own plane z = 0. Never inside, as in POV-Ray.
struct PolygonShape {
  using Description = Polygon;
  static Primitive build(const Polygon& description, const Matrix& world_from_object);
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

// The cylinder behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/quadric_shapes.hpp"

namespace povtrace::render::shapes {

// cylinder (cylinder.cpp): the canonical unit cylinder of quadric_shapes.hpp, built by make_cylinder.
struct CylinderShape {
  using Description = Cylinder;
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static Primitive build(const Cylinder& description, const Matrix& world_from_object) {
    return make_cylinder(description, world_from_object);
  }
};

}  // namespace povtrace::render::shapes

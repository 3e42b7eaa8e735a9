// The cone behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/quadric_shapes.hpp"

namespace povtrace::render::shapes {

// cone (cone.cpp): the canonical cone of quadric_shapes.hpp. A Cone description can build a cylinder primitive
// (make_cone: equal radii, as POV-Ray makes it one).
struct ConeShape {
  using Description = Cone;
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static Primitive build(const Cone& description, const Matrix& world_from_object) {
    return make_cone(description, world_from_object);
  }
};

}  // namespace povtrace::render::shapes

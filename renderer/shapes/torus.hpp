// The torus behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/quadric_shapes.hpp"

namespace povtrace::render::shapes {

// torus (torus.cpp): a.x = major radius, a.y = minor radius around +y; b.x = 1 with sturm.
struct TorusShape {
  using Description = Torus;
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
  static Primitive build(const Torus& description, const Matrix& world_from_object) {
    return make_torus(description, world_from_object);
  }
};

}  // namespace povtrace::render::shapes

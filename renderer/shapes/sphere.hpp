// The sphere behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

// sphere (sphere.cpp): a = centre, radius, in object space.
struct SphereShape {
  using Description = Sphere;
  static Primitive build(const Sphere& description, const Matrix& world_from_object);
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
};

}  // namespace povtrace::render::shapes

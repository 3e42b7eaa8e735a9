// The box behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

// box (box.cpp): a = lo corner, b = hi corner. A hit's element is the face the slab test entered or left by.
struct BoxShape {
  using Description = Box;
  static Primitive build(const Box& description, const Matrix& world_from_object);
  static Intersections intersect(const Primitive& p, const Ray& ray);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
  static Vec3 face_normal(const Primitive& p, std::uint32_t side);   // POV-Ray's Side1/Side2
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3) { return face_normal(*hit.leaf, hit.element); }
};

}  // namespace povtrace::render::shapes

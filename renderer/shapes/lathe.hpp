// The lathe behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/many_roots.hpp"
#include "renderer/shapes/solid_shapes.hpp"
#include "renderer/shapes/sweep.hpp"

namespace povtrace::render::shapes {

// lathe (lathe.cpp): LatheData. A hit's element is the profile segment, its u the segment parameter w there.
struct LatheShape {
  using Description = Lathe;
  static void roots(const Primitive& p, const Ray& ray, RootList& out);   // appends every root
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
  static Primitive build(const Lathe& description, const Matrix& world_from_object) {
    return make_lathe(description, world_from_object);
  }
  static Vec3 normal_at(const Primitive& p, std::uint32_t segment, double w, Vec3 world_point);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point) {
    return normal_at(*hit.leaf, hit.element, hit.u, world_point);
  }
};

}  // namespace povtrace::render::shapes

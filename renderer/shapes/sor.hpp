// The sor behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
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

// sor (sor.cpp): SorData. A hit's element is the profile segment, or the base or cap disc.
struct SorShape {
  using Description = Sor;
  static void roots(const Primitive& p, const Ray& ray, RootList& out);   // appends every root
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
  static Primitive build(const Sor& description, const Matrix& world_from_object) {
    return make_sor(description, world_from_object);
  }
  static Vec3 normal_at(const Primitive& p, std::uint32_t element, Vec3 world_point);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point) { return normal_at(*hit.leaf, hit.element, world_point); }
};

}  // namespace povtrace::render::shapes

// The superellipsoid behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/many_roots.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace povtrace::render::shapes {

// superellipsoid (superellipsoid.cpp): a = the powers 2/e, e/n, 2/n.
struct SuperellipsoidShape {
  using Description = Superellipsoid;
  static void roots(const Primitive& p, const Ray& ray, RootList& out);   // appends every root
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static Primitive build(const Superellipsoid& description, const Matrix& world_from_object) {
    return make_superellipsoid(description, world_from_object);
  }
};

}  // namespace povtrace::render::shapes

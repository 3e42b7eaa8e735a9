// The ovus behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/many_roots.hpp"

namespace povtrace::render::shapes {

Primitive make_ovus(const Ovus& description, const Matrix& world_from_object);

// ovus (ovus.cpp): a = (bottom radius, top radius, spindle tube radius), b = (spindle centre height, its circle's
// radius, the height below which the bottom sphere is the surface), radius = the height above which the top one is.
struct OvusShape {
  using Description = Ovus;
  static void roots(const Primitive& p, const Ray& ray, RootList& out);   // appends every root
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
  static Primitive build(const Ovus& description, const Matrix& world_from_object) {
    return make_ovus(description, world_from_object);
  }
};

}  // namespace povtrace::render::shapes

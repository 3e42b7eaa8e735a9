// The mesh behind the shape interface (registered in shape_list.hpp; the dispatch is shape_registry.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include "scene/description.hpp"
#include "renderer/build_context.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/triangle_shapes.hpp"

namespace povtrace::render::shapes {

// mesh and mesh2 (mesh.cpp): MeshShapeData shared by every placement of one mesh; any number of roots. A hit's
// element is the triangle, u and v its barycentric coordinates there.
struct MeshShape {
  using Description = Mesh;
  static Primitive build(const Mesh& description, const Matrix& world_from_object, const BuildContext& context);
  static void collect(const Primitive& p, const Ray& ray, HitBuffer& out);   // appends every hit
  static std::optional<SurfaceHit> nearest(const Primitive& p, const Ray& ray, double t_min, double t_max);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
  static std::array<double, 2> uv(const SurfaceHit& hit, Vec3 world_point);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point);
};

}  // namespace povtrace::render::shapes

// What an isosurface keeps once built (solid_build.cpp builds it, isosurface.cpp intersects it), and the ray's span
// through its container as POV-Ray computes it (isosurface_container.cpp).
#pragma once

#include <memory>
#include <optional>

#include "scene/description.hpp"
#include "renderer/build_context.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/many_roots.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace povtrace::render {

struct IsosurfaceData : ShapeData {
  std::shared_ptr<const sdl::FunctionValue> function;
  bool sphere_container = false;
  Vec3 corner1, corner2;   // box container
  Vec3 centre;             // sphere container
  double radius = 1;
  double threshold = 0, accuracy = 0.001, max_gradient = 1.1;
  int max_trace = 1;
  bool closed = true;
  bool evaluate = false;
  std::array<double, 3> evaluate_params{0, 0, 0};   // P0, P1, P2
  int noise_generator = 2;   // the scene's (global_settings), which the function reads (f_noise3d, patterns)
};

// Where a ray runs through the container: depths t1 ≤ t2 (world units) and the box faces it enters and leaves by
// (1…6 for −x, +x, −y, +y, −z, +z, as POV-Ray numbers them; 0 for none or a sphere).
struct ContainerSpan {
  double t1 = 0, t2 = 0;
  int side1 = 0, side2 = 0;
};
// The box container met by the object-space ray p + t·d (d as transformed, not normalised): POV-Ray's Box::Intersect.
std::optional<ContainerSpan> box_container_span(Vec3 p, Vec3 d, Vec3 corner1, Vec3 corner2);
// The sphere container met by the object-space ray p + t·d with d unit length: POV-Ray's Sphere::Intersect.
std::optional<ContainerSpan> sphere_container_span(Vec3 p, Vec3 d, Vec3 centre, double radius);

std::shared_ptr<IsosurfaceData> isosurface_data(const Isosurface& iso);
// With `evaluate`: raises d.max_gradient to the bound learnt from a fixed set of probe rays (isosurface.cpp), where
// POV-Ray's rays start from the bound learnt by the rays rendered before them. d must be complete (noise generator
// included). Nothing without `evaluate`.
void learn_evaluate_gradient(IsosurfaceData& d);

}  // namespace povtrace::render

namespace povtrace::render::shapes {

// isosurface (isosurface.cpp, isosurface_container.cpp): IsosurfaceData in object space. A hit's element is the
// container face it lies on (0 for the function's own surface).
struct IsosurfaceShape {
  using Description = Isosurface;
  // The data carries the scene's noise generator, which its function reads (f_noise3d and its like).
  static Primitive build(const Isosurface& description, const Matrix& world_from_object, const BuildContext& context);
  static void roots(const Primitive& p, const Ray& ray, RootList& out);   // appends every root
  static Vec3 normal_at(const Primitive& p, std::uint32_t side, Vec3 world_point);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point) { return normal_at(*hit.leaf, hit.element, world_point); }
  static Vec3 normal(const Primitive& p, Vec3 world_point) { return normal_at(p, 0, world_point); }
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

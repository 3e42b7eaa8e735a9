// What an isosurface keeps once built (solid_build.cpp builds it, isosurface.cpp intersects it), and the ray's span
// through its container as POV-Ray computes it (isosurface_container.cpp).
#pragma once

#include <memory>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

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
  int noise_generator = 2;   // the scene's (global_settings), which the function reads (f_noise3d, patterns)
};

// Where a ray runs through the container: depths t1 ≤ t2 (world units) and the box faces it enters and leaves by
// (1…6 for −x, +x, −y, +y, −z, +z, as POV-Ray numbers them; 0 for none or a sphere).
struct ContainerSpan {
  double t1 = 0, t2 = 0;
  int side1 = 0, side2 = 0;
};
// The box container met by the object-space ray p + t·d (d as transformed, not normalised): POV-Ray's Box::Intersect.
bool box_container_span(Vec3 p, Vec3 d, Vec3 corner1, Vec3 corner2, ContainerSpan& span);
// The sphere container met by the object-space ray p + t·d with d unit length: POV-Ray's Sphere::Intersect.
bool sphere_container_span(Vec3 p, Vec3 d, Vec3 centre, double radius, ContainerSpan& span);

std::shared_ptr<IsosurfaceData> isosurface_data(const Isosurface& iso);

}  // namespace povtrace::render

// Embree 3's BVH over one mesh's triangles, for nearest hits only (renderer/shapes/mesh.cpp MeshShape::nearest).
//
// Why: on the bench's 100k-triangle torus, finding the nearest triangle through Embree made povtrace's whole render
// 2.6x faster than its own TriangleBvh walk (1.5x at 10k triangles), images unchanged. Embree answers in single
// precision, so it only *picks* the triangle: the depth and weights povtrace shades with are still its own
// watertight double-precision test of that triangle, with the mesh's tolerances; when that test disagrees (a ray
// grazing an edge), the caller walks its own BVH. Hits of every triangle (CSG, shadows through transparent
// meshes, inside tests) always use the own BVH.
#pragma once

#include <cstdint>
#include <memory>
#include <vector>

#include "renderer/geometry.hpp"

namespace povtrace::render {

class EmbreeMesh {
 public:
  // The triangles `faces` (three vertex indices each) over `vertices` (x y z each), copied into Embree's padded
  // buffers; null if Embree cannot be started on this machine (the own BVH then answers alone).
  static std::unique_ptr<EmbreeMesh> build(const std::vector<float>& vertices, const std::vector<std::uint32_t>& faces);
  ~EmbreeMesh();
  EmbreeMesh(const EmbreeMesh&) = delete;
  EmbreeMesh& operator=(const EmbreeMesh&) = delete;

  // The triangle whose crossing by the ray (object space, unit direction) is nearest within [t_min, t_max], as
  // Embree finds it in single precision; false if it finds none.
  bool nearest(const Ray& ray, double t_min, double t_max, std::uint32_t& triangle) const;

 private:
  explicit EmbreeMesh(void* scene) : scene_(scene) {}
  void* scene_;   // RTCScene (kept opaque so that this header needs no Embree include)
};

}  // namespace povtrace::render

// The triangle-based shapes' render-side data (triangle.cpp, polygon.cpp, mesh.cpp) and how a primitive is set up
// from a description; their shape interfaces are triangle.hpp, polygon.hpp and mesh.hpp.
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <vector>

#include "scene/description.hpp"
#include "renderer/accel/embree_mesh.hpp"
#include "renderer/accel/triangle_bvh.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

// triangle / smooth_triangle, in world space (POV-Ray moves a triangle's vertices by its transforms).
struct TriangleData : ShapeData {
  std::array<Vec3, 3> corners;
  std::array<Vec3, 3> normals;   // smooth: the world-space vertex normals
  bool smooth = false;
  bool degenerate = false;       // never hit
};

// polygon: its points in its own plane (z = 0 of the primitive's object space).
struct PolygonData : ShapeData {
  std::vector<std::array<double, 2>> points;
  bool degenerate = false;       // never hit
};

// mesh / mesh2: the parser's arrays and a BVH over them, in object space; one per mesh, shared by every placement.
struct MeshShapeData : ShapeData {
  std::shared_ptr<const MeshData> data;
  TriangleBvh bvh;
  // Embree's BVH over the same triangles for nearest hits (renderer/accel/embree_mesh.hpp), made by
  // prepare_embree_mesh for the meshes a scene lets use it; null until then, or if Embree cannot start.
  mutable std::once_flag embree_once;
  mutable std::unique_ptr<EmbreeMesh> embree;
};

// Fill in a primitive whose common fields (material, transform, flags) are already set.
void set_up_triangle(Primitive& p, const Triangle& triangle);
void set_up_polygon(Primitive& p, const Polygon& polygon);
// A mesh's shape and BVH, built once per mesh and shared by its placements (renderer/shared_meshes.hpp).
std::shared_ptr<const MeshShapeData> make_mesh_shape(const std::shared_ptr<const MeshData>& data);
void set_up_mesh(Primitive& p, std::shared_ptr<const MeshShapeData> shape);
// Lets a placed mesh find its nearest hits through Embree (Primitive::embree_nearest), building Embree's BVH once
// per mesh; leaves it on the own BVH if Embree cannot start.
void prepare_embree_mesh(Primitive& p);

}  // namespace povtrace::render::shapes

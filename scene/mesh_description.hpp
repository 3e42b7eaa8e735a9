// Scene-description forms of the triangle-based shapes (povray-sdl-and-geometry.md §8): triangle, smooth_triangle,
// polygon, mesh and mesh2. Included by description.hpp; kept apart so the shapes' data layout reads in one place.
//
// A mesh is stored flat (single-precision vertex and normal arrays, index arrays) and shared: a declared mesh
// placed a thousand times copies one pointer per placement, never the triangles. Only the textures, which every
// placement transforms on its own (POV-Ray's Mesh::Copy copies them, Mesh::Transform moves them), live per object.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "vecmath.hpp"

namespace povtrace {

struct Texture;

// triangle { P1, P2, P3 } and smooth_triangle { P1, N1, P2, N2, P3, N3 } in object space, as written.
struct Triangle {
  std::array<Vec3, 3> corners;
  std::optional<std::array<Vec3, 3>> normals;   // smooth_triangle: the vertex normals, unit length
  bool degenerate = false;   // POV-Ray's DEGENERATE_FLAG (zero area, zero normal, normals on both sides): no hits
};

// polygon { n, P1 … Pn }: the points in the polygon's own plane coordinates (POV-Ray's Compute_Polygon), each
// sub-polygon closed by repeating its first point (the parser appends the closing point when missing).
struct Polygon {
  std::vector<std::array<double, 2>> points;
  Matrix world_from_plane;   // the plane frame: (x, y, 0) in plane coordinates → object space
  bool degenerate = false;   // collinear or non-coplanar points: POV-Ray never hits such a polygon
};

// The triangles of a mesh or mesh2, as flat arrays.
struct MeshData {
  static constexpr std::uint32_t flat = 0xffffffffu;   // face_normals entry of a flat triangle
  std::vector<float> vertices;              // x y z per vertex: POV-Ray keeps mesh vertices in single precision
  std::vector<float> normals;               // x y z per smooth normal, unit length, single precision
  std::vector<std::uint32_t> faces;         // three vertex indices per triangle (degenerate ones already dropped)
  std::vector<std::uint32_t> face_normals;  // three normal indices per triangle (flat: all three `flat`); empty
                                            // when no triangle is smooth
  // Three texture indices per triangle into Mesh::textures: -1 in the first = the mesh's own texture; -1 in the
  // second = a single texture; all three set = a texture_list whose colours are blended across the triangle.
  // Empty when no triangle has a texture of its own.
  std::vector<std::int32_t> face_textures;
  // uv_vectors: u v per coordinate (double, as POV-Ray keeps them) and three indices into them per triangle. Empty
  // when none were given: every triangle's corners are <0, 0> (POV-Ray's default).
  std::vector<double> uvs;
  std::vector<std::uint32_t> face_uvs;
  std::optional<Vec3> inside_vector;        // unit; absent: the mesh has no inside (POV-Ray's PATCH_OBJECT)
  // x y z per triangle: POV-Ray's stored flat normal of a mesh { } triangle, (P3 − P1) × (P2 − P1) of the corners
  // as written (double precision), normalised, in single precision. Empty for a mesh2, whose flat normals POV-Ray
  // computes from the single-precision corners (the mesh camera reads them).
  std::vector<float> flat_normals;
  std::size_t triangle_count() const { return faces.size() / 3; }
  Vec3 vertex(std::uint32_t i) const { return {vertices[3 * i], vertices[3 * i + 1], vertices[3 * i + 2]}; }
  Vec3 normal(std::uint32_t i) const { return {normals[3 * i], normals[3 * i + 1], normals[3 * i + 2]}; }
};

struct Mesh {
  std::shared_ptr<const MeshData> data;
  std::vector<std::shared_ptr<const Texture>> textures;   // the per-triangle textures, moved with the object
};

// POV-Ray's Mesh::Inside: the parity of the mesh's triangles crossed by a ray from the world point. The ray leaves
// along inside_vector taken as a *world* direction and carried into object space (POV-Ray's own reading of it);
// crossings count at object-space depths in (1e-6, 1e7). Requires data.inside_vector.
bool mesh_inside(const MeshData& data, const Matrix& world_from_object, Vec3 world_point);

}  // namespace povtrace

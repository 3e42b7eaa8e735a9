// POV-Ray 3.7's mesh_camera, ready to make rays (facts: docs/issue21-mesh-camera.md, from POV-Ray's
// tracepixel.cpp CreateCameraRay MESH_CAMERA, mesh.cpp Compute_Mesh_Triangle / Smooth_Mesh_Normal and
// parse.cpp Parse_Mesh_Camera). Each pixel's rays leave the faces of the camera's meshes, along their normals.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

struct RenderMeshCamera {
  // A mesh with what the rays need per face, in POV-Ray's precision: the flat normal (single precision, from the
  // corners as POV-Ray orders them), and for `smooth` the interpolation frame of compute_smooth_triangle.
  struct CameraMesh {
    std::shared_ptr<const MeshData> data;
    bool transformed = false;
    Matrix world_from_object, object_from_world;
    std::vector<std::array<float, 3>> flat_normals;
    std::vector<std::uint8_t> swapped;           // POV-Ray swapped the face's first two corners
    std::vector<std::array<float, 3>> perp;      // smooth: the scaled perpendicular of compute_smooth_triangle
    std::vector<std::uint8_t> v_axis;            // smooth: the dominant axis of the third edge
    std::size_t faces() const { return data->triangle_count(); }
  };
  unsigned rays_per_pixel = 1;
  unsigned distribution = 0;
  bool smooth = false;
  double offset = 0;    // the camera location's z: how far along the face normal rays start (mesh space)
  bool flip = false;    // the camera direction's z is negative: rays go against the face normals
  std::vector<CameraMesh> meshes;
  std::vector<std::size_t> face_totals;   // running face counts (distribution 1)
  // Distribution 3: for each tenth of u and of v, a bit per face of the first mesh whose uv triangle reaches it
  // (POV-Ray's U_Xref / V_Xref; the search goes through the faces in both, lowest index first).
  std::vector<std::uint32_t> u_buckets[10], v_buckets[10];
};

// `location_z`, `direction_z`: the camera's, after its transforms (the offset along the normals and the flip).
std::shared_ptr<const RenderMeshCamera> make_mesh_camera(const MeshCamera& camera, double location_z,
                                                         double direction_z);

// Ray `ray_number` of the pixel sample at (x, y) after POV-Ray's centre shift (x + ½, y − ½), or none: no face there
// (POV-Ray then traces nothing: black, fully transparent). The direction is not normalised yet.
std::optional<Ray> mesh_camera_ray(const RenderMeshCamera& camera, double x, double y, int width, int height,
                                   unsigned ray_number);

}  // namespace povtrace::render

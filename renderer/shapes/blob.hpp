// A blob's components as POV-Ray's Make_Blob leaves them (blob_build.cpp builds them, blob.cpp intersects them).
#pragma once

#include <memory>
#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/many_roots.hpp"
#include "renderer/shapes/solid_shapes.hpp"

namespace povtrace::render {

struct BlobElement {
  enum class Kind { sphere, ellipsoid, base_hemisphere, apex_hemisphere, cylinder } kind = Kind::sphere;
  Vec3 centre;              // sphere, ellipsoid
  double radius2 = 0;
  double length = 0;        // cylinder and its hemispheres: the axis runs along z from 0 to length
  double c[3] = {0, 0, 0};  // density c0·r⁴ + c1·r² + c2 inside radius² (r² the squared distance)
  bool transformed = false; // ellipsoid, cylinder, hemispheres
  Matrix element_from_blob; // their inverse transform
  std::uint32_t component = 0;   // the written component it comes from (a cylinder gives three elements)
};

struct BlobData : ShapeData {
  double threshold = 1;
  bool sturm = false;
  std::uint32_t textured_components = 0;   // components with materials of their own (0: none has a texture)
  std::vector<BlobElement> elements;
};

std::shared_ptr<BlobData> blob_data(const Blob& b);

}  // namespace povtrace::render

namespace povtrace::render::shapes {

// POV-Ray's Blob::Determine_Textures at a world point on a blob with component textures (material of component k is
// p.element_materials + k): each element whose field reaches the point adds its component's material with weight
// |field|, the weights (single precision, as POV-Ray's) then scaled to sum to 1.
void blob_materials(const Primitive& p, Vec3 world_point, MaterialBlend& blend);
// A blob with component textures: how many components (materials p.element_materials + 0 … count − 1), else 0.
std::uint32_t blob_texture_count(const Primitive& p);

// blob (blob.cpp, built by blob_build.cpp): BlobData in object space.
struct BlobShape {
  using Description = Blob;
  static Primitive build(const Blob& description, const Matrix& world_from_object) {
    return make_blob(description, world_from_object);
  }
  static void roots(const Primitive& p, const Ray& ray, RootList& out);   // appends every root
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

// A height field's samples, shared by every primitive placed from the same description (height_field_build.cpp
// reads them, height_field.cpp intersects them).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/description.hpp"
#include "renderer/build_context.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/many_roots.hpp"

namespace povtrace::render {

struct HeightFieldData : ShapeData {
  int width = 0, depth = 0;              // samples along x and z; cells are (width − 1) × (depth − 1)
  std::vector<std::uint16_t> heights;    // row z = 0 first
  std::vector<std::array<std::int16_t, 3>> normals;   // `smooth`: 32767 · the unit vertex normal, per sample
  double bottom = 0, top = 0;            // the bounding box's y range (bottom is also POV-Ray's inside "water")
  bool smooth = false;
  double height(int x, int z) const { return heights[static_cast<std::size_t>(z) * width + x]; }
};

// Samples `heights` (width × depth, row z = 0 first) as a height field: the bounding box from the heights and
// water_level, the `smooth` vertex normals.
std::shared_ptr<HeightFieldData> height_field_data(std::vector<std::uint16_t> heights, int width, int depth,
                                                   double water_level, bool smooth);
// The height field primitive of `data` placed by the object's transforms (after POV-Ray's unit-cube scaling).
Primitive place_height_field(std::shared_ptr<const HeightFieldData> data, const Matrix& world_from_object);

}  // namespace povtrace::render

namespace povtrace::render::shapes {

// height_field (height_field.cpp, built by height_field_build.cpp): HeightFieldData in the unit-cell space of
// place_height_field. A hit's element is the triangle: 2 · cell + (upper triangle).
struct HeightFieldShape {
  using Description = HeightField;
  // Reads the image (or samples the pigment function) now; a missing or unreadable file is a ParseError at the
  // file name in the scene.
  static Primitive build(const HeightField& description, const Matrix& world_from_object, const BuildContext& context);
  static void roots(const Primitive& p, const Ray& ray, RootList& out);   // appends every root
  // The flat triangle's (or smoothed) normal: the one hit decides (POV-Ray keeps its normal with the intersection).
  static Vec3 normal_at(const Primitive& p, std::uint32_t element, Vec3 world_point);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point) { return normal_at(*hit.leaf, hit.element, world_point); }
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

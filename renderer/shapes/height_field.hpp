// A height field's samples, shared by every primitive placed from the same description (height_field_build.cpp
// reads them, height_field.cpp intersects them).
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "renderer/geometry.hpp"

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

// Mesh shapes shared by the placements of one mesh: a mesh declared once and placed many times shares its
// triangles (one MeshData behind every placement's Mesh), and so gets one BVH instead of one per placement.
#pragma once

#include <memory>
#include <unordered_map>

#include "scene/description.hpp"
#include "renderer/shapes/triangle_shapes.hpp"

namespace povtrace::render {

// Lives as long as one scene build (or one parse's geometry queries) and is passed to what builds primitives. It
// holds every MeshData it has seen, so no other mesh can take one's place while it lives, and it is gone with the
// build: the primitives then own their shapes.
class SharedMeshes {
 public:
  // The shape built for `data` (its BVH), built on first use.
  std::shared_ptr<const shapes::MeshShapeData> shape_for(const std::shared_ptr<const MeshData>& data);

 private:
  std::unordered_map<std::shared_ptr<const MeshData>, std::shared_ptr<const shapes::MeshShapeData>> built_;
};

}  // namespace povtrace::render

#include "renderer/shared_meshes.hpp"

namespace povtrace::render {

std::shared_ptr<const shapes::MeshShapeData> SharedMeshes::shape_for(const std::shared_ptr<const MeshData>& data) {
  auto& shape = built_[data];
  if (!shape) shape = shapes::make_mesh_shape(data);
  return shape;
}

}  // namespace povtrace::render

#include "parser/description_transforms.hpp"

namespace povtrace {

void transform_texture(std::shared_ptr<const Texture>& texture, const Matrix& m) {
  if (!texture) return;
  auto moved = std::make_shared<Texture>(*texture);
  for (auto& layer : moved->layers) {
    layer.pigment.world_from_pattern = layer.pigment.world_from_pattern * m;
    if (layer.normal) {
      auto normal = std::make_shared<Normal>(*layer.normal);
      normal->pattern.world_from_pattern = normal->pattern.world_from_pattern * m;
      layer.normal = std::move(normal);
    }
  }
  texture = std::move(moved);
}

void transform_object(Object& object, const Matrix& m) {
  transform_texture(object.texture, m);
  for (auto& clip : object.clipped_by) transform_object(clip, m);
  for (auto& bound : object.bounded_by) transform_object(bound, m);
  for (auto& bound : object.removed_bounds) transform_object(bound, m);
  if (auto* csg = std::get_if<Csg>(&object.shape)) {
    for (auto& child : csg->children) transform_object(child, m);
    for (auto& light : csg->lights) transform_light(light, m);
    return;
  }
  if (auto* mesh = std::get_if<Mesh>(&object.shape))   // a mesh's per-triangle textures move with it
    for (auto& texture : mesh->textures) transform_texture(texture, m);
  if (auto* text = std::get_if<Text>(&object.shape)) text->box_transforms.push_back(m);   // extents, as CSG::Transform
  object.world_from_object = object.world_from_object * m;
}

void transform_light(Light& light, const Matrix& m) {
  light.location = m.point(light.location);
  light.point_at = m.point(light.point_at);
  light.axis1 = m.vector(light.axis1);   // the area's axes turn and scale with the light, as directions
  light.axis2 = m.vector(light.axis2);
  for (Object& o : light.looks_like) transform_object(o, m);
}

}  // namespace povtrace

#include "scene/description_transforms.hpp"

namespace povtrace {

void transform_pattern(Pigment& p, const Matrix& m) { p.world_from_pattern = p.world_from_pattern * m; }

void transform_media(std::shared_ptr<const std::vector<Media>>& media, const Matrix& m) {
  if (!media) return;
  bool any_density = false;
  for (const Media& x : *media) any_density = any_density || !x.densities.empty();
  if (!any_density) return;   // constant media: nothing moves
  auto moved = std::make_shared<std::vector<Media>>(*media);
  for (Media& x : *moved)
    for (Pigment& d : x.densities) transform_pattern(d, m);
  media = std::move(moved);
}

namespace {

// Box::Translate and Box::Scale move a box's corners (re-sorted per axis) while it has no transform of its own.
void fold_into_corners(Box& box, const Matrix& m) {
  const Vec3 a = m.point(box.corner1), b = m.point(box.corner2);
  box.corner1 = min(a, b);
  box.corner2 = max(a, b);
}

}  // namespace

bool transform_keeps_sphere(TransformKind kind, const Matrix& m) {
  if (kind == TransformKind::translate || kind == TransformKind::rotate) return true;
  return kind == TransformKind::scale && m.m[0][0] == m.m[1][1] && m.m[0][0] == m.m[2][2];
}

std::shared_ptr<const Texture> transformed_texture(const Texture& texture, const Matrix& m) {
  auto moved = std::make_shared<Texture>(texture);
  if (texture.pattern) {
    auto pattern = std::make_shared<TexturePattern>(*texture.pattern);
    transform_pattern(pattern->pattern, m);
    moved->pattern = std::move(pattern);
  }
  for (auto& layer : moved->layers) {
    transform_pattern(layer.pigment, m);
    if (layer.normal) {
      auto normal = std::make_shared<Normal>(*layer.normal);
      transform_pattern(normal->pattern, m);
      layer.normal = std::move(normal);
    }
  }
  return moved;
}

void transform_texture(std::shared_ptr<const Texture>& texture, const Matrix& m) {
  if (texture) texture = transformed_texture(*texture, m);
}

bool texture_ignores_transforms(const Texture& texture) {
  if (texture.pattern) return false;
  for (const TextureLayer& layer : texture.layers)
    if (layer.normal || layer.pigment.pattern != PatternKind::solid) return false;
  return true;
}

// The inverse POV-Ray keeps with a transform (Compute_Translation_Transform, Compute_Scaling_Transform,
// Compute_Rotation_Transform: −v, 1/s, the rotation's transpose); a general matrix is inverted.
Matrix povray_inverse(const Matrix& m, TransformKind kind) {
  switch (kind) {
    case TransformKind::translate: return Matrix::translation({-m.m[3][0], -m.m[3][1], -m.m[3][2]});
    case TransformKind::scale: return Matrix::scaling({1.0 / m.m[0][0], 1.0 / m.m[1][1], 1.0 / m.m[2][2]});
    case TransformKind::rotate: {
      Matrix t;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) t.m[i][j] = m.m[j][i];
      return t;
    }
    case TransformKind::other: break;
  }
  return m.inverse();
}

void transform_object(Object& object, const Matrix& m, TransformKind kind, ObjectTransformObserver* observer) {
  if (observer) observer->transforming(object, m, kind);
  // A texture that ignores transforms stays as it is: moving it would only copy it (for every moved copy of a
  // declared object). The parser keeps those transforms in its notes in case the texture is edited later.
  if (!object.uv_mapping && object.texture && !texture_ignores_transforms(*object.texture))
    transform_texture(object.texture, m);
  if (!object.uv_mapping && object.interior_texture && !texture_ignores_transforms(*object.interior_texture))
    transform_texture(object.interior_texture, m);
  // The interior's media densities move with the object, uv-mapped or not (POV-Ray's Interior::Transform in
  // Transform_Object and friends).
  if (object.interior) transform_media(object.interior->media, m);
  for (auto& clip : object.clipped_by) transform_object(clip, m, kind, observer);
  for (auto& bound : object.bounded_by) transform_object(bound, m, kind, observer);
  for (auto& bound : object.removed_bounds) transform_object(bound, m, kind, observer);
  if (auto* csg = std::get_if<Csg>(&object.shape)) {
    for (auto& child : csg->children) transform_object(child, m, kind, observer);
    for (auto& light : csg->lights) transform_light(light, m, observer);
    return;
  }
  if (auto* mesh = std::get_if<Mesh>(&object.shape); mesh && !object.uv_mapping)
    for (auto& texture : mesh->textures) transform_texture(texture, m);   // a mesh's triangle textures move with it
  if (auto* blob = std::get_if<Blob>(&object.shape); blob && !object.uv_mapping)
    for (auto& texture : blob->textures)   // as Blob::Transform moves each Element_Texture
      if (texture && !texture_ignores_transforms(*texture)) transform_texture(texture, m);
  // A bicubic_patch keeps no matrix: POV-Ray moves its control points (MTransPoint) and subdivides them as they are.
  if (auto* patch = std::get_if<BicubicPatch>(&object.shape)) {
    for (Vec3& p : patch->points) p = m.point(p);
    return;
  }
  // Every transform of a julia_fractal runs its Compute_BBox, which clears its inversion (POV-Ray 3.7's Fractal).
  if (auto* julia = std::get_if<JuliaFractal>(&object.shape)) {
    object.inverse = false;
    julia->object_from_world = povray_inverse(m, kind) * julia->object_from_world;
  }
  if (auto* poly = std::get_if<Poly>(&object.shape)) poly->object_from_world = povray_inverse(m, kind) * poly->object_from_world;
  if (auto* sphere = std::get_if<Sphere>(&object.shape); sphere && !transform_keeps_sphere(kind, m))
    sphere->ellipsoid = true;
  if (auto* box = std::get_if<Box>(&object.shape)) {
    if (!box->rotated && (kind == TransformKind::translate || kind == TransformKind::scale)) {
      fold_into_corners(*box, m);
      return;
    }
    box->rotated = true;
  }
  object.world_from_object = object.world_from_object * m;
}

void transform_light(Light& light, const Matrix& m, ObjectTransformObserver* observer) {
  light.location = m.point(light.location);
  light.point_at = m.point(light.point_at);
  light.axis1 = m.vector(light.axis1);   // the area's axes turn and scale with the light, as directions
  light.axis2 = m.vector(light.axis2);
  for (Object& o : light.looks_like) transform_object(o, m, TransformKind::other, observer);
  for (Object& o : light.projected_through) transform_object(o, m, TransformKind::other, observer);
}

}  // namespace povtrace

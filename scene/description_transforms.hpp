// Transforms of finished description values, shared by the interpreter (object and light modifiers) and the
// renderer (which rescales whole scenes, renderer/scene_scale.cpp).
#pragma once

#include <memory>

#include "scene/description.hpp"

namespace povtrace {

// The texture's patterns move with the object: every layer's pigment and normal pattern space, or a patterned
// texture's pattern (its textures are evaluated in its space). Copied, since textures are shared.
std::shared_ptr<const Texture> transformed_texture(const Texture& texture, const Matrix& m);
void transform_texture(std::shared_ptr<const Texture>& texture, const Matrix& m);

// A pattern's space moves by m (composed after its own transforms and warps).
void transform_pattern(Pigment& p, const Matrix& m);
// Media densities move by m (copied, since media lists are shared).
void transform_media(std::shared_ptr<const std::vector<Media>>& media, const Matrix& m);

// Whether no transform can change how the texture renders: plain layers whose pigments are solid colours (no
// pattern space is ever read for them) and which have no normal.
bool texture_ignores_transforms(const Texture& texture);

// How a transform was written: boxes fold translations and scalings into their corners until they are rotated
// (POV-Ray's Box::Translate, Box::Scale).
enum class TransformKind { translate, rotate, scale, other };

// The inverse of the transform m of that kind as POV-Ray keeps it beside the matrix (exact for translate, scale and
// rotate; a general matrix is inverted).
Matrix povray_inverse(const Matrix& m, TransformKind kind);

// Sphere::Translate, Sphere::Rotate and a uniform Sphere::Scale keep a sphere a sphere; any other transform makes it
// POV-Ray's ellipsoid (Sphere::ellipsoid), for good.
bool transform_keeps_sphere(TransformKind kind, const Matrix& m);

// What a transform must also move that the description does not hold: the parser's notes on the objects it is
// building (parser/objects/object_transform.hpp). Told of the object transformed and of every object the transform
// reaches through it (clip and bounding objects, removed bounds, CSG children, looks_like objects of lights), each
// before the transform changes it, so that it sees the object as it was (its matrix, a sphere not yet an ellipsoid).
class ObjectTransformObserver {
 public:
  virtual ~ObjectTransformObserver() = default;
  virtual void transforming(Object& object, const Matrix& m, TransformKind kind) = 0;
};

// A transform moves the object, what is attached to it (textures — unless the object is uv-mapped, POV-Ray's
// UV_FLAG, or the texture ignores transforms —, clip and bounding objects), and for CSG every child and
// light inside (POV-Ray transforms a CSG by transforming its children; the node keeps no matrix). `observer`, when
// given, is told of each object moved.
void transform_object(Object& object, const Matrix& m, TransformKind kind = TransformKind::other,
                      ObjectTransformObserver* observer = nullptr);

// A light's location, point_at and area axes (as directions), and its looks_like object (`observer` as above).
void transform_light(Light& light, const Matrix& m, ObjectTransformObserver* observer = nullptr);

}  // namespace povtrace

// Transforms of finished description values, shared by the interpreter (object and light modifiers) and the
// renderer (which rescales whole scenes, renderer/scene_scale.cpp).
#pragma once

#include <memory>

#include "parser/description.hpp"

namespace povtrace {

// The texture's patterns move with the object: every layer's pigment and normal pattern space, or a patterned
// texture's pattern (its textures are evaluated in its space). Copied, since textures are shared.
std::shared_ptr<const Texture> transformed_texture(const Texture& texture, const Matrix& m);
void transform_texture(std::shared_ptr<const Texture>& texture, const Matrix& m);

// How a transform was written: boxes fold translations and scalings into their corners until they are rotated
// (POV-Ray's Box::Translate, Box::Scale).
enum class TransformKind { translate, rotate, scale, other };

// A transform moves the object, what is attached to it (textures — unless the object is uv-mapped, POV-Ray's
// UV_FLAG —, clip and bounding objects), and for CSG every child and light inside (POV-Ray transforms a CSG by
// transforming its children; the node keeps no matrix).
void transform_object(Object& object, const Matrix& m, TransformKind kind = TransformKind::other);

// A light's location, point_at and area axes (as directions), and its looks_like object.
void transform_light(Light& light, const Matrix& m);

}  // namespace povtrace

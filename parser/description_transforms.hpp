// Transforms of finished description values, shared by the interpreter (object and light modifiers) and the
// renderer (which rescales whole scenes, renderer/scene_scale.cpp).
#pragma once

#include <memory>

#include "parser/description.hpp"

namespace povtrace {

// The texture's patterns move with the object: every layer's pigment and normal pattern space (copied, since
// textures are shared).
void transform_texture(std::shared_ptr<const Texture>& texture, const Matrix& m);

// A transform moves the object, what is attached to it (textures, clip and bounding objects), and for CSG every
// child and light inside (POV-Ray transforms a CSG by transforming its children; the node keeps no matrix).
void transform_object(Object& object, const Matrix& m);

// A light's location, point_at and area axes (as directions), and its looks_like object.
void transform_light(Light& light, const Matrix& m);

}  // namespace povtrace

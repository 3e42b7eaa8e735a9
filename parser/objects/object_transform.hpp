// Transforms of the objects and lights the parser is building: the description's own transforms
// (scene/description_transforms.hpp) with the parser's notes on every object moved along (ObjectNotes), as POV-Ray's
// Transform moves the bounding box it holds.
#pragma once

#include "scene/description_transforms.hpp"

namespace povtrace::sdl {

void transform_noted(Object& object, const Matrix& m, TransformKind kind = TransformKind::other);
void transform_noted(Light& light, const Matrix& m);

}  // namespace povtrace::sdl

// Transforms of the objects and lights the parser is building: the description's own transforms
// (scene/description_transforms.hpp) with the parser's notes on every object moved along (ObjectNotes), as POV-Ray's
// Transform moves the bounding box it holds.
#pragma once

#include "parser/extents/object_notes.hpp"
#include "scene/description_transforms.hpp"

namespace povtrace::sdl {

// `pool`: where notes the objects get are made (the parse's).
void transform_noted(Object& object, const Matrix& m, const NotesPool& pool, TransformKind kind = TransformKind::other);
void transform_noted(Light& light, const Matrix& m, const NotesPool& pool);

// Applies the transforms deferred for the object's texture (ObjectNotes::deferred_texture_transform, their
// composition in written order), as they would have been applied when written; the texture is then the object's own
// copy.
void apply_deferred_texture_transforms(Object& object, const NotesPool& pool);

// Forgets them: the texture they were kept for is replaced, or the object is placed with a texture they cannot change.
void drop_deferred_texture_transforms(Object& object, const NotesPool& pool);

}  // namespace povtrace::sdl

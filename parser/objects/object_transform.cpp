#include "parser/objects/object_transform.hpp"

#include "parser/extents/object_notes.hpp"

namespace povtrace::sdl {

namespace {
// Told of each object before the transform moves it. Notes are only edited when they change, so that the copies of
// a declared object keep sharing theirs and an object without notes gets none for nothing.
class NotesFollowTransforms final : public ObjectTransformObserver {
 public:
  void transforming(Object& object, const Matrix& m, TransformKind) override {
    // CSG::Transform, Quadric::Transform, Blob::Transform, Mesh::Transform: the box itself is carried.
    if (const auto& carried = notes_of(object).carried_extent) {
      const ExtentBox moved = carried->transformed(m);   // before edit_notes, which may replace what `carried` is in
      edit_notes(object).carried_extent = moved;
    }
    // A shape's own transform remakes its box from the shape, without the narrowing by clip objects (a CSG node
    // has no box of its own to remake: its children are transformed).
    if (!std::holds_alternative<Csg>(object.shape) && !notes_of(object).box_skips_clips)
      edit_notes(object).box_skips_clips = true;
  }
};
}  // namespace

void transform_noted(Object& object, const Matrix& m, TransformKind kind) {
  NotesFollowTransforms notes;
  transform_object(object, m, kind, &notes);
}

void transform_noted(Light& light, const Matrix& m) {
  NotesFollowTransforms notes;
  transform_light(light, m, &notes);
}

}  // namespace povtrace::sdl

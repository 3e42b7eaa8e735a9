#include "parser/objects/object_transform.hpp"

#include "parser/extents/object_notes.hpp"

namespace povtrace::sdl {

namespace {
// Sphere::Transform: the first transform that does not keep the sphere a sphere makes it an ellipsoid, holding the
// centre and radius as moved so far (`so_far`: similarities only, translations, rotations, uniform scales); every
// transform from then on composes into the ellipsoid's own transform.
void carry_sphere_frame(Object& object, const Sphere& sphere, const Matrix& so_far, TransformKind kind,
                        const Matrix& m, const NotesPool& pool) {
  if (!sphere.ellipsoid) {
    if (transform_keeps_sphere(kind, m)) return;
    const double scale = length(Vec3{so_far.m[0][0], so_far.m[0][1], so_far.m[0][2]});
    edit_notes(object, pool).ellipsoid_frame = SphereEllipsoidFrame{so_far.point(sphere.centre), sphere.radius * scale, m};
    return;
  }
  if (!notes_of(object).ellipsoid_frame) return;   // an ellipsoid built in code: its box comes from world_from_object
  SphereEllipsoidFrame& frame = *edit_notes(object, pool).ellipsoid_frame;
  frame.since = frame.since * m;
}

// Plane::Transform: a matrix or transform block gives the plane a transform, starting from the normal and distance
// it had (moved by translate, rotate and scale so far); every transform from then on composes into it.
void carry_plane_frame(Object& object, const Plane& plane, const Matrix& so_far, TransformKind kind,
                       const Matrix& m, const NotesPool& pool) {
  if (!notes_of(object).matrix_frame) {
    if (kind != TransformKind::other) return;
    const Vec3 n = normalize(so_far.inverse().normal_from_inverse(plane.normal));
    const double d = dot(n, so_far.point(plane.normal * plane.distance));
    edit_notes(object, pool).matrix_frame = PlaneMatrixFrame{n, d, m};
    return;
  }
  PlaneMatrixFrame& frame = *edit_notes(object, pool).matrix_frame;
  frame.since = frame.since * m;
}

// Told of each object before the transform moves it (its matrix and shape as they were). Notes are only edited when
// they change, so that the copies of a declared object keep sharing theirs and an object without notes gets none for
// nothing.
class NotesFollowTransforms final : public ObjectTransformObserver {
 public:
  explicit NotesFollowTransforms(const NotesPool& notes_pool) : pool(notes_pool) {}

  void transforming(Object& object, const Matrix& m, TransformKind kind) override {
    // The texture moves with the object (transform_object) unless it ignores transforms: those are kept here, and the
    // ones kept before reach a texture that no longer ignores them (edited since) before this one does.
    if (!object.uv_mapping && object.texture) {
      if (texture_ignores_transforms(*object.texture)) {
        std::optional<Matrix>& kept = edit_notes(object, pool).deferred_texture_transform;
        kept = kept ? *kept * m : m;
      } else {
        apply_deferred_texture_transforms(object, pool);
      }
    }
    // CSG::Transform, Quadric::Transform, Blob::Transform, Mesh::Transform: the box itself is carried.
    if (const auto& carried = notes_of(object).carried_extent) {
      const ExtentBox moved = carried->transformed(m);   // before edit_notes, which may replace what `carried` is in
      edit_notes(object, pool).carried_extent = moved;
    }
    // A shape's own transform remakes its box from the shape, without the narrowing by clip and bounding objects (a
    // CSG node has no box of its own to remake: its children are transformed). Noted only for an object that has
    // any: lists gain objects only inside the object's modifiers, whose end (modifiers_ended) clears this anyway,
    // so an object without them would get notes for nothing.
    if (!std::holds_alternative<Csg>(object.shape) && !notes_of(object).box_skips_clips && narrowed_by_any(object))
      edit_notes(object, pool).box_skips_clips = true;
    if (const auto* sphere = std::get_if<Sphere>(&object.shape))
      carry_sphere_frame(object, *sphere, object.world_from_object, kind, m, pool);
    if (const auto* plane = std::get_if<Plane>(&object.shape))
      carry_plane_frame(object, *plane, object.world_from_object, kind, m, pool);
    if (std::holds_alternative<Poly>(object.shape) && !object.clipped_by.empty() &&
        !notes_of(object).box_from_first_clip)
      edit_notes(object, pool).box_from_first_clip = true;
  }

 private:
  // The lists whose boxes narrow the object's at the end of its modifiers (ObjectExtents::narrowed).
  static bool narrowed_by_any(const Object& o) {
    return !o.clipped_by.empty() || !o.bounded_by.empty() || !o.removed_bounds.empty();
  }

  const NotesPool& pool;
};
}  // namespace

void transform_noted(Object& object, const Matrix& m, const NotesPool& pool, TransformKind kind) {
  NotesFollowTransforms notes(pool);
  transform_object(object, m, kind, &notes);
}

void transform_noted(Light& light, const Matrix& m, const NotesPool& pool) {
  NotesFollowTransforms notes(pool);
  transform_light(light, m, &notes);
}

void apply_deferred_texture_transforms(Object& object, const NotesPool& pool) {
  if (const std::optional<Matrix> kept = notes_of(object).deferred_texture_transform) {
    transform_texture(object.texture, *kept);
    edit_notes(object, pool).deferred_texture_transform.reset();
  }
}

void drop_deferred_texture_transforms(Object& object, const NotesPool& pool) {
  if (notes_of(object).deferred_texture_transform) edit_notes(object, pool).deferred_texture_transform.reset();
}

}  // namespace povtrace::sdl

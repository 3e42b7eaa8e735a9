#include "parser/objects/object_transform.hpp"

#include "parser/extents/object_notes.hpp"

namespace povtrace::sdl {

namespace {
// Sphere::Transform: the first transform that does not keep the sphere a sphere makes it an ellipsoid, holding the
// centre and radius as moved so far (`so_far`: similarities only, translations, rotations, uniform scales); every
// transform from then on composes into the ellipsoid's own transform.
void carry_sphere_frame(Object& object, const Sphere& sphere, const Matrix& so_far, TransformKind kind,
                        const Matrix& m) {
  if (!sphere.ellipsoid) {
    if (transform_keeps_sphere(kind, m)) return;
    const double scale = length(Vec3{so_far.m[0][0], so_far.m[0][1], so_far.m[0][2]});
    edit_notes(object).ellipsoid_frame = SphereEllipsoidFrame{so_far.point(sphere.centre), sphere.radius * scale, m};
    return;
  }
  if (!notes_of(object).ellipsoid_frame) return;   // an ellipsoid built in code: its box comes from world_from_object
  SphereEllipsoidFrame& frame = *edit_notes(object).ellipsoid_frame;
  frame.since = frame.since * m;
}

// Plane::Transform: a matrix or transform block gives the plane a transform, starting from the normal and distance
// it had (moved by translate, rotate and scale so far); every transform from then on composes into it.
void carry_plane_frame(Object& object, const Plane& plane, const Matrix& so_far, TransformKind kind,
                       const Matrix& m) {
  if (!notes_of(object).matrix_frame) {
    if (kind != TransformKind::other) return;
    const Vec3 n = normalize(so_far.inverse().normal_from_inverse(plane.normal));
    const double d = dot(n, so_far.point(plane.normal * plane.distance));
    edit_notes(object).matrix_frame = PlaneMatrixFrame{n, d, m};
    return;
  }
  PlaneMatrixFrame& frame = *edit_notes(object).matrix_frame;
  frame.since = frame.since * m;
}

// Told of each object before the transform moves it (its matrix and shape as they were). Notes are only edited when
// they change, so that the copies of a declared object keep sharing theirs and an object without notes gets none for
// nothing.
class NotesFollowTransforms final : public ObjectTransformObserver {
 public:
  void transforming(Object& object, const Matrix& m, TransformKind kind) override {
    // The texture moves with the object (transform_object) unless it ignores transforms: those are kept here, and the
    // ones kept before reach a texture that no longer ignores them (edited since) before this one does.
    if (!object.uv_mapping && object.texture) {
      if (texture_ignores_transforms(*object.texture)) {
        const std::optional<Matrix>& kept = notes_of(object).deferred_texture_transform;
        const Matrix composed = kept ? *kept * m : m;
        edit_notes(object).deferred_texture_transform = composed;
      } else {
        apply_deferred_texture_transforms(object);
      }
    }
    // CSG::Transform, Quadric::Transform, Blob::Transform, Mesh::Transform: the box itself is carried.
    if (const auto& carried = notes_of(object).carried_extent) {
      const ExtentBox moved = carried->transformed(m);   // before edit_notes, which may replace what `carried` is in
      edit_notes(object).carried_extent = moved;
    }
    // A shape's own transform remakes its box from the shape, without the narrowing by clip objects (a CSG node
    // has no box of its own to remake: its children are transformed).
    if (!std::holds_alternative<Csg>(object.shape) && !notes_of(object).box_skips_clips)
      edit_notes(object).box_skips_clips = true;
    if (const auto* sphere = std::get_if<Sphere>(&object.shape))
      carry_sphere_frame(object, *sphere, object.world_from_object, kind, m);
    if (const auto* plane = std::get_if<Plane>(&object.shape))
      carry_plane_frame(object, *plane, object.world_from_object, kind, m);
    if (std::holds_alternative<Poly>(object.shape) && !object.clipped_by.empty() &&
        !notes_of(object).box_from_first_clip)
      edit_notes(object).box_from_first_clip = true;
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

void apply_deferred_texture_transforms(Object& object) {
  if (const std::optional<Matrix> kept = notes_of(object).deferred_texture_transform) {
    transform_texture(object.texture, *kept);
    edit_notes(object).deferred_texture_transform.reset();
  }
}

void drop_deferred_texture_transforms(Object& object) {
  if (notes_of(object).deferred_texture_transform) edit_notes(object).deferred_texture_transform.reset();
}

}  // namespace povtrace::sdl

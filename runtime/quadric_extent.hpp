// The bounding box POV-Ray 3.7 gives a quadric (shape/quadrics.cpp), as min_extent() and max_extent() report it,
// and the pieces it is made from: the coefficients a transform leaves, the half space an axis-aligned plane gives
// a CSG intersection, the box the coefficients give inside a clip range. Pure computations on the parser's
// description types; the interpreter decides when POV-Ray runs each (below).
//
// When POV-Ray computes a quadric's box:
//   - Parse_Quadric: once, from the coefficients as written, clip range ±BOUND_HUGE (not ±BOUND_HUGE/2), the old box
//     being the constructor's huge one: parsed_quadric_box().
//   - Each later transform (Quadric::Transform) transforms the coefficients (transformed_quadric) and only carries
//     the box along (ExtentBox::transformed, Recompute_BBox); the box is not recomputed from the new coefficients.
//   - clipped_by on a quadric (Parse_Object_Mods): quadric_box() from the coefficients as they are then, the clip
//     range ±BOUND_HUGE narrowed by the non-inverted clip objects (plane_min_max for planes, their boxes otherwise),
//     the old box being the quadric's current one.
//   - A CSG intersection (CSG::Compute_BBox): the children other than quadrics and height fields narrow a range from
//     ±BOUND_HUGE (planes by plane_min_max, the rest by their boxes); then each quadric child, in order, gets
//     quadric_box() of its current (transformed) coefficients in that range with its current box as the old one —
//     the child's own box is replaced — and narrows the range in turn. Children with INVERTED_FLAG are skipped: an
//     inverted quadric or box is, an inverted plane is not (Plane::Invert flips it without the flag).
#pragma once

#include "scene/description.hpp"
#include "scene/description_transforms.hpp"
#include "scene/extent_box.hpp"

namespace povtrace {

// The box of a newly constructed POV-Ray object (ObjectBase's constructor; Quadric's constructor leaves it): the
// huge box, lower corner -BOUND_HUGE/2, lengths BOUND_HUGE. The `old` box of Parse_Quadric's computation.
ExtentBox initial_quadric_box();

// Quadric::Transform's coefficients (with Quadric_To_Matrix and Matrix_To_Quadric): the 4×4 coefficient matrix,
// upper triangular as the terms are written, multiplied by the transform's inverse on the left and its transpose on
// the right, the symmetric pairs then summed back into the mixed and linear terms. `m` is one transform in
// povtrace's row-vector layout (points p' = p·m). POV-Ray transforms the coefficients once per transform written,
// with the inverse each kind of transform carries (scale: the reciprocals, rotate: the transpose, translate: the
// negated vector, matrix: MInvers); `kind` picks that inverse, so applying this per transform in written order
// reproduces POV-Ray's coefficients to the last bit, and applying it once to a composition agrees to rounding.
// TransformKind::other stands for `matrix` (and a transform block, whose inverse POV-Ray composes from its parts'
// inverses — agreeing to rounding); a matrix not of its kind's shape (a scale with a translation, say) is treated
// as `other`. Cannot fail for the non-singular transforms the parser accepts.
Quadric transformed_quadric(const Quadric& q, const Matrix& m, TransformKind kind = TransformKind::other);
// The same with the inverse given (its 4×3 layout; the fourth column is taken as 0, 0, 0, 1).
Quadric transformed_quadric_by_inverse(const Quadric& q, const Matrix& inverse);

// Quadric::Compute_Plane_Min_Max: the range a plane confines a CSG intersection (or a quadric's clipped_by) to.
// Only a plane perpendicular to an axis (the normal's other two components below EPSILON) limits that axis, from
// above when the normal's component is positive (max = d), from below when negative (min = -d); every other bound is
// ±BOUND_HUGE/2.
//
// While no `matrix` or `transform` block has reached the plane, POV-Ray keeps it in world space (Plane::Translate,
// Rotate, Scale move its unit normal and distance): this form takes the plane as povtrace's description holds it —
// `normal` (unit, as written) and `distance` as written — and the object's composed world_from_object, finds the
// world unit normal and distance (as inside() does), and applies the rule. An inverted plane (a difference's later
// child; POV-Ray's Plane::Invert negates both and sets no INVERTED_FLAG, so the plane still counts) is passed with
// `normal` and `distance` negated.
void plane_min_max(Vec3 normal, double distance, const Matrix& world_from_object, Vec3& min, Vec3& max);
// Once a `matrix` or `transform` block has reached the plane, POV-Ray keeps the normal and distance it had then and
// composes every transform since into the plane's Trans; Compute_Plane_Min_Max then uses the normal multiplied by
// Trans's forward linear part (MInvTransNormal — not the inverse transpose a normal needs), and the distance
// -Distance - P·N + 1 with P that normal carried back by Trans's inverse as a point. That is not the transformed
// plane's half space in general (a translation along the normal and the identity come out right); reproduced as is.
// `normal` and `distance` are the unit normal and the distance (as written, not POV-Ray's negated Distance) the
// plane had when its Trans was created — negated for an inverted plane —, `trans` the composition of the transforms
// since.
void plane_min_max_with_trans(Vec3 normal, double distance, const Matrix& trans, Vec3& min, Vec3& max);

// Quadric::Compute_BBox(ClipMin, ClipMax) without its loop over the quadric's clip objects (the caller narrows
// clip_min and clip_max by them first): the box POV-Ray holds after it, given the quadric's current coefficients and
// its box on entry (`old`).
//   - Coefficients below EPSILON in magnitude count as 0 (the mixed and linear terms halved first).
//   - Any mixed term left: the clip range's box if its volume (in double) is below the old box's (BOUNDS_VOLUME,
//     the product of the float lengths), else the old box — with no CRITICAL_LENGTH check.
//   - Otherwise linear terms move the quadric to its centre (the vertex along an axis without a square term), A is
//     made non-negative, and the centred ellipsoid, the cylinders, cones and one-sheet hyperboloids along each axis,
//     and the paraboloids along each axis give a box (their remaining axes ±BOUND_HUGE/2), intersected with the clip
//     range. It replaces the old box only when its volume is smaller; a box then wider than CRITICAL_LENGTH on an
//     axis becomes the huge box.
// `computed` says whether the box computed from the shape replaced the old one: POV-Ray then sets Automatic_Bounds,
// which lets Link_To_Frame drop a quadric's bounded_by, and never clears it (a caller keeping that flag ORs this in).
struct QuadricBox {
  ExtentBox box;
  bool computed = false;
};
QuadricBox quadric_box(const Quadric& current, Vec3 clip_min, Vec3 clip_max, const ExtentBox& old);

// Parse_Quadric's box: quadric_box(written, ±BOUND_HUGE, initial_quadric_box()).
QuadricBox parsed_quadric_box(const Quadric& written);

}  // namespace povtrace

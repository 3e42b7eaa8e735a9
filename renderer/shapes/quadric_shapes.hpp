// Render-ready primitives for cylinder, cone, disc and torus built from their scene descriptions, the way POV-Ray
// 3.7 builds its own shape objects at parse time (canonical shapes placed by a transform). Used by
// render_scene.cpp and by the geometry tests.
//
// Primitive fields used by these shapes (all tests are done in the canonical object space):
// - cylinder: the unit cylinder x² + y² = 1, 0 <= z <= 1; b.x = 1 when capped (not `open`).
// - cone: the cone x² + y² = z², radius = dist (z of the small end, the canonical base), 1 >= z >= dist; the big end
//   is the cap at z = 1 with radius 1; b.x = 1 when capped.
// - disc: the plane z = 0, a.x = hole radius², a.y = outer radius²; b = the world unit normal.
// - torus: a.x = major radius R, a.y = minor radius r, in the XZ plane around +y; b.x = 1 with `sturm`.
#pragma once

#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

// POV-Ray's Compute_Coordinate_Transform: scale <radius, radius, axis_length>, then the rotation taking +z to the unit
// vector `up` (about the axis <−up.y, up.x, 0>, or no rotation / a half turn about x when up is within EPSILON of
// ±z), then a translation to `origin`.
Matrix canonical_frame(Vec3 origin, Vec3 up, double radius, double axis_length);

// Each returns the primitive in object space placed by `world_from_object` (the object's own transforms);
// material, object index, shadow and inverse flags are left to the caller.
Primitive make_cylinder(const Cylinder& c, const Matrix& world_from_object);
Primitive make_cone(const Cone& c, const Matrix& world_from_object);   // a cylinder when POV-Ray makes it one
Primitive make_disc(const Disc& d, const Matrix& world_from_object);
Primitive make_torus(const Torus& t, const Matrix& world_from_object);

}  // namespace povtrace::render

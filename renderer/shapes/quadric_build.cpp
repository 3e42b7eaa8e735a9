// Builds cylinder, cone, disc and torus primitives from their descriptions (see quadric_shapes.hpp). Facts from
// POV-Ray 3.7 (source/backend/shape/cones.cpp Compute_Cone_Data/Compute_Cylinder_Data, discs.cpp Compute_Disc,
// source/backend/math/matrices.cpp Compute_Coordinate_Transform, 3.7-stable):
// - A cylinder's canonical z runs from 0 at its second point to 1 at its first, scaled by the radius across.
// - A cone whose radii differ by less than EPSILON is a cylinder with the first radius. Otherwise the bigger end
//   becomes the canonical z = 1 (radius 1); the axis is extended to where the radius reaches 0 (the canonical
//   origin), and dist = the small end's z. If (r_big − r_small)·length / extended_length < EPSILON the cone is a
//   cylinder after all (radius r_big). The arithmetic is kept as POV-Ray does it, so a negative radius gives the
//   same double cone POV-Ray renders.
// - A disc is the canonical plane z = 0 placed by the frame (centre, normal, 1, 1); its shading normal is the
//   written normal carried by the object's transforms and normalised.
#include "renderer/shapes/quadric_shapes.hpp"

#include <cmath>
#include <utility>

namespace povtrace::render {

namespace {
constexpr double kEpsilon = tolerance::epsilon;

// Rodrigues' rotation by `angle` (radians) about the unit axis `k`, as a row-vector matrix.
Matrix axis_rotation(Vec3 k, double angle) {
  const double c = std::cos(angle), s = std::sin(angle), t = 1.0 - c;
  Matrix r;
  const Vec3 images[3] = {Vec3{c + k.x * k.x * t, k.x * k.y * t + k.z * s, k.x * k.z * t - k.y * s},
                          Vec3{k.x * k.y * t - k.z * s, c + k.y * k.y * t, k.y * k.z * t + k.x * s},
                          Vec3{k.x * k.z * t + k.y * s, k.y * k.z * t - k.x * s, c + k.z * k.z * t}};
  for (int row = 0; row < 3; ++row) r.m[row] = {images[row].x, images[row].y, images[row].z};
  return r;
}

Primitive placed(ShapeType type, const Matrix& frame, const Matrix& world_from_object) {
  Primitive p;
  p.type = type;
  p.transformed = true;
  p.world_from_object = frame * world_from_object;
  p.object_from_world = p.world_from_object.inverse();
  return p;
}

// Compute_Cylinder_Data: the canonical cylinder from `base` (z = 0) to `apex` (z = 1).
Primitive cylinder_between(Vec3 apex, Vec3 base, double radius, bool open, const Matrix& world_from_object) {
  const Vec3 axis = apex - base;
  const double len = length(axis);
  Primitive p = placed(ShapeType::cylinder, canonical_frame(base, axis * (1.0 / len), radius, len), world_from_object);
  p.radius = 0.0;
  p.b.x = open ? 0.0 : 1.0;
  return p;
}
}  // namespace

Matrix canonical_frame(Vec3 origin, Vec3 up, double radius, double axis_length) {
  Vec3 axis{-up.y, up.x, 0.0};
  double cos_angle = up.z;
  if (std::abs(up.z) > 1.0 - kEpsilon) {
    axis = Vec3{1, 0, 0};
    cos_angle = up.z < 0.0 ? -1.0 : 1.0;
  }
  axis = axis * (1.0 / length(axis));   // POV-Ray normalises the rotation axis
  return Matrix::scaling({radius, radius, axis_length}) * axis_rotation(axis, std::acos(cos_angle)) *
         Matrix::translation(origin);
}

Primitive make_cylinder(const Cylinder& c, const Matrix& world_from_object) {
  return cylinder_between(c.end1, c.end2, c.radius, c.open, world_from_object);
}

Primitive make_cone(const Cone& c, const Matrix& world_from_object) {
  Vec3 apex = c.end1, base = c.end2;
  double apex_radius = c.radius1, base_radius = c.radius2;
  if (std::abs(apex_radius - base_radius) < kEpsilon)
    return cylinder_between(apex, base, apex_radius, c.open, world_from_object);
  if (apex_radius < base_radius) {   // the bigger end at the top
    std::swap(apex, base);
    std::swap(apex_radius, base_radius);
  }
  Vec3 axis = apex - base;
  const double len = length(axis);
  axis = axis * (1.0 / len);
  const double below_base = base_radius * len / (apex_radius - base_radius);
  const Vec3 origin = base - axis * below_base;
  const double extended_length = below_base + len;
  if ((apex_radius - base_radius) * len / extended_length < kEpsilon)
    return cylinder_between(apex, base, apex_radius, c.open, world_from_object);
  Primitive p = placed(ShapeType::cone, canonical_frame(origin, axis, apex_radius, extended_length), world_from_object);
  p.radius = below_base / extended_length;
  p.b.x = c.open ? 0.0 : 1.0;
  return p;
}

Primitive make_disc(const Disc& d, const Matrix& world_from_object) {
  Primitive p = placed(ShapeType::disc, canonical_frame(d.centre, d.normal, 1.0, 1.0), world_from_object);
  p.a = Vec3{d.hole_radius * d.hole_radius, d.radius * d.radius, 0.0};
  const Vec3 n = world_from_object.inverse().normal_from_inverse(d.normal);
  p.b = n * (1.0 / std::sqrt(dot(n, n)));
  return p;
}

Primitive make_torus(const Torus& t, const Matrix& world_from_object) {
  Primitive p;
  p.type = ShapeType::torus;
  p.transformed = !(world_from_object == Matrix::identity());
  p.world_from_object = world_from_object;
  if (p.transformed) p.object_from_world = world_from_object.inverse();
  p.a = Vec3{t.major, t.minor, 0.0};
  p.b.x = t.sturm ? 1.0 : 0.0;
  return p;
}

}  // namespace povtrace::render

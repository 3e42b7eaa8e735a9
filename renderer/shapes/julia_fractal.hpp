// A julia_fractal placed in the scene (julia_fractal.cpp): the 4-D fractal of julia_fractal_math.hpp in its object
// space, reached through the object's transform.
#pragma once

#include <array>
#include <memory>
#include <optional>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/julia_fractal_math.hpp"

namespace povtrace::render {

struct JuliaFractalData : ShapeData {
  julia::Fractal fractal;
};

}  // namespace povtrace::render

namespace povtrace::render::shapes {

// julia_fractal (julia_fractal.cpp): the first hit of the march, or every hit for a CSG child or a clipped fractal
// (POV-Ray's IS_CHILD_OBJECT). The point and normal found with a hit are kept for it (its element): the normal comes
// from the orbit there, and the point from the bisection, which the depth along the ray would not reproduce.
struct JuliaFractalShape {
  using Description = JuliaFractal;
  static Primitive build(const JuliaFractal& description, const Matrix& world_from_object);
  static void collect(const Primitive& p, const Ray& ray, HitBuffer& out);
  static std::optional<SurfaceHit> nearest(const Primitive& p, const Ray& ray, double t_min, double t_max);
  static Vec3 hit_normal(const SurfaceHit& hit, Vec3 world_point);
  static Vec3 hit_point(const SurfaceHit& hit);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds object_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

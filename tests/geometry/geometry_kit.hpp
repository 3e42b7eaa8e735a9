// Helpers shared by the geometry tests (sphere, plane, box, accelerator): primitives built in code, rays and the
// seeded random directions and transforms the randomised checks draw from.
#pragma once

#include <gtest/gtest.h>

#include <random>

#include "renderer/geometry.hpp"

namespace povtrace::test {

// A sphere of `radius` around `centre` in object space.
inline render::Primitive sphere(Vec3 centre, double radius) {
  render::Primitive p;
  p.type = render::ShapeType::sphere;
  p.a = centre;
  p.radius = radius;
  return p;
}

// An axis-aligned box with opposite corners `lo` and `hi` in object space.
inline render::Primitive box(Vec3 lo, Vec3 hi) {
  render::Primitive p;
  p.type = render::ShapeType::box;
  p.a = lo;
  p.b = hi;
  return p;
}

// The plane at `distance` along the (normalised) `normal`, as POV-Ray's plane { normal, distance }.
inline render::Primitive plane(Vec3 normal, double distance) {
  render::Primitive p;
  p.type = render::ShapeType::plane;
  p.a = normalize(normal);
  p.radius = distance;
  return p;
}

// `p` placed in the world by `world_from_object` (the inverse is computed here).
inline render::Primitive transformed(render::Primitive p, const Matrix& world_from_object) {
  p.transformed = true;
  p.world_from_object = world_from_object;
  p.object_from_world = world_from_object.inverse();
  return p;
}

// A ray from `origin` along `direction`, normalised.
inline render::Ray ray(Vec3 origin, Vec3 direction) { return render::Ray{origin, normalize(direction)}; }

// A uniformly distributed unit vector (normalised Gaussian triple).
inline Vec3 random_unit(std::mt19937& rng) {
  std::normal_distribution<double> g(0.0, 1.0);
  for (;;) {
    const Vec3 v{g(rng), g(rng), g(rng)};
    const double l = length(v);
    if (l > 1e-3) return v / l;
  }
}

// Random scale 0.3–3 per axis, then rotation ±180° about each axis, then translation ±5 per axis.
inline Matrix random_transform(std::mt19937& rng) {
  std::uniform_real_distribution<double> s(0.3, 3.0), ang(-180.0, 180.0), tr(-5.0, 5.0);
  return Matrix::scaling({s(rng), s(rng), s(rng)}) * Matrix::rotation({ang(rng), ang(rng), ang(rng)}) *
         Matrix::translation({tr(rng), tr(rng), tr(rng)});
}

// As random_transform, but one time in five the scale along `mirror_axis` (0 = x, 1 = y, 2 = z) is negated.
inline Matrix random_mirroring_transform(std::mt19937& rng, int mirror_axis) {
  std::uniform_real_distribution<double> s(0.3, 3.0), ang(-180.0, 180.0), tr(-5.0, 5.0), coin(0.0, 1.0);
  Vec3 scale{s(rng), s(rng), s(rng)};
  if (coin(rng) < 0.2) scale[mirror_axis] = -scale[mirror_axis];
  return Matrix::scaling(scale) * Matrix::rotation({ang(rng), ang(rng), ang(rng)}) *
         Matrix::translation({tr(rng), tr(rng), tr(rng)});
}

// Traces `rays` seeded random rays (origin coordinates pos(rng)·1.5, random unit directions) through the BVH and by
// brute force; each must give the same closest hit (depth and primitive). Returns how many hits `counted` accepts,
// so that a test can check its own shapes were reached and not only the fillers around them.
template <class Counted>
int bvh_hits_equal_to_brute_force(const render::Accelerator& acc, std::mt19937& rng,
                                  std::uniform_real_distribution<double>& pos, int rays, Counted counted) {
  int count = 0;
  for (int k = 0; k < rays; ++k) {
    const render::Ray r{{pos(rng) * 1.5, pos(rng) * 1.5, pos(rng) * 1.5}, random_unit(rng)};
    const render::Hit fast = acc.closest_hit(r, render::tolerance::min_isect_depth, render::tolerance::bound_huge);
    const render::Hit slow =
        acc.closest_hit_brute_force(r, render::tolerance::min_isect_depth, render::tolerance::bound_huge);
    EXPECT_EQ(fast.found(), slow.found()) << "ray " << k;
    if (!fast.found() || !slow.found()) continue;
    EXPECT_EQ(fast.t, slow.t) << "ray " << k;
    EXPECT_EQ(fast.primitive, slow.primitive) << "ray " << k;
    count += counted(fast.primitive) ? 1 : 0;
  }
  return count;
}

}  // namespace povtrace::test

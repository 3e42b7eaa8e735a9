// The ray in a shape's own space, as POV-Ray's lathe, prism, sor and isosurface code takes it.
#pragma once

#include "renderer/geometry.hpp"

namespace povtrace::render {

// A ray in a shape's own space with its direction normalised, and the length L of the world direction there
// (object depth / L = world depth). As POV-Ray does for these shapes, the direction is always normalised, by
// multiplying with 1/L, even without a transform: in the ill-conditioned cubics of nearly level rays the last bits
// decide which wrong roots come out.
struct LocalRay {
  Vec3 p, d;
  double len = 1;
};
inline LocalRay local_ray(const Primitive& prim, const Ray& ray) {
  LocalRay r{ray.origin, ray.direction, 1.0};
  if (prim.transformed) {
    r.p = prim.object_from_world.point(ray.origin);
    r.d = prim.object_from_world.vector(ray.direction);
  }
  r.len = length(r.d);
  r.d = r.d * (1.0 / r.len);
  return r;
}

}  // namespace povtrace::render

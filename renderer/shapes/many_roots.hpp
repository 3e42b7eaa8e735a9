// The shapes whose rays can meet them more often than Intersections holds (superellipsoid, blob, lathe, sor,
// prism, height_field): each appends its roots to a RootList, and many_roots.cpp answers intersect_all,
// collect_hits and nearest_hit for all of them from that list.
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/geometry.hpp"

namespace povtrace::render::shapes {

// One root: the world depth along the unit world ray, which part of the shape it is on (a height field's
// triangle, the profile segment or end disc of a lathe, prism or sor, the container face of an isosurface; 0 for
// the others) and where on that part
// (the segment parameter w of a lathe or prism; it becomes the SurfaceHit's u).
struct Root {
  double t = 0;
  std::uint32_t element = 0;
  double u = 0;
};
using RootList = std::vector<Root>;

bool has_many_roots(ShapeType type);
// Appends every root of p along the ray (world depths, already filtered by the shape's own depth rules).
void append_roots(const Primitive& p, const Ray& ray, RootList& out);

// The geometry.hpp queries for these shapes (intersect_all keeps the nearest Intersections::capacity roots).
Intersections first_roots(const Primitive& p, const Ray& ray);
void collect_many_roots(const Primitive& p, const Ray& ray, HitBuffer& out);
bool nearest_of_many_roots(const Primitive& p, const Ray& ray, double t_min, double t_max, SurfaceHit& hit);

void superellipsoid_roots(const Primitive& p, const Ray& ray, RootList& out);
void height_field_roots(const Primitive& p, const Ray& ray, RootList& out);
void blob_roots(const Primitive& p, const Ray& ray, RootList& out);
void lathe_roots(const Primitive& p, const Ray& ray, RootList& out);
void prism_roots(const Primitive& p, const Ray& ray, RootList& out);
void sor_roots(const Primitive& p, const Ray& ray, RootList& out);
void isosurface_roots(const Primitive& p, const Ray& ray, RootList& out);

}  // namespace povtrace::render::shapes

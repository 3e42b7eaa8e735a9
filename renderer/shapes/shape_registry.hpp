// The dispatch over the registered shapes (shape_list.hpp): visit_shape turns a ShapeType into a call on the
// shape's struct through one switch generated from the list, and the adapters below supply what a shape leaves
// out (a shape declares only the operations it has; see any renderer/shapes/<shape>.hpp):
// - hits: intersect (at most Intersections::capacity depth-sorted roots), or roots (any number, many_roots.hpp),
//   or collect + nearest (CSG, text, meshes);
// - normal, and hit_normal where the hit (its element, u, v) decides the normal; hit_point where the depth does not
//   give the hit's point back;
// - inside (false without: triangles and polygons are never inside, inverse or not, as in POV-Ray);
// - object_bounds (carried to world here) or world_bounds; uv (else the world point's x and y);
// - build from the description (else the description is built elsewhere: CSG in renderer/csg_build.cpp).
// The switch costs what a hand-written one does: no virtual call, and each case inlines its adapter.
#pragma once

#include <concepts>
#include <optional>
#include <type_traits>

#include "scene/description.hpp"
#include "renderer/build_context.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/shape_list.hpp"

#include "renderer/shapes/bicubic_patch.hpp"
#include "renderer/shapes/blob.hpp"
#include "renderer/shapes/box.hpp"
#include "renderer/shapes/cone.hpp"
#include "renderer/shapes/csg.hpp"
#include "renderer/shapes/cylinder.hpp"
#include "renderer/shapes/disc.hpp"
#include "renderer/shapes/height_field.hpp"
#include "renderer/shapes/isosurface.hpp"
#include "renderer/shapes/julia_fractal.hpp"
#include "renderer/shapes/lathe.hpp"
#include "renderer/shapes/many_roots.hpp"
#include "renderer/shapes/mesh.hpp"
#include "renderer/shapes/plane.hpp"
#include "renderer/shapes/poly.hpp"
#include "renderer/shapes/polygon.hpp"
#include "renderer/shapes/prism.hpp"
#include "renderer/shapes/quadric.hpp"
#include "renderer/shapes/sor.hpp"
#include "renderer/shapes/sphere.hpp"
#include "renderer/shapes/superellipsoid.hpp"
#include "renderer/shapes/ovus.hpp"
#include "renderer/shapes/text.hpp"
#include "renderer/shapes/torus.hpp"
#include "renderer/shapes/triangle.hpp"

namespace povtrace::render::shapes {

template <class S>
concept HasIntersect = requires(const Primitive& p, const Ray& r) {
  { S::intersect(p, r) } -> std::same_as<Intersections>;
};
template <class S>
concept HasRoots = requires(const Primitive& p, const Ray& r, RootList& out) { S::roots(p, r, out); };
template <class S>
concept HasCollect = requires(const Primitive& p, const Ray& r, HitBuffer& out) {
  S::collect(p, r, out);
  { S::nearest(p, r, 0.0, 0.0) } -> std::same_as<std::optional<SurfaceHit>>;
};
template <class S>
concept HasHitNormal = requires(const SurfaceHit& h, Vec3 w) { { S::hit_normal(h, w) } -> std::same_as<Vec3>; };
template <class S>
concept HasHitPoint = requires(const SurfaceHit& h) { { S::hit_point(h) } -> std::same_as<Vec3>; };
template <class S>
concept HasInside = requires(const Primitive& p, Vec3 w) { { S::inside(p, w) } -> std::same_as<bool>; };
template <class S>
concept HasObjectBounds = requires(const Primitive& p) { { S::object_bounds(p) } -> std::same_as<Bounds>; };
template <class S>
concept HasUv = requires(const SurfaceHit& h, Vec3 w) { { S::uv(h, w) } -> std::same_as<std::array<double, 2>>; };
template <class S>
concept HasBuild = requires(const typename S::Description& d, const Matrix& m) { S::build(d, m); };
// A shape whose build reads the scene build's context (shared meshes, the scene's noise generator).
template <class S>
concept HasContextBuild = requires(const typename S::Description& d, const Matrix& m, const BuildContext& c) {
  S::build(d, m, c);
};

// Calls visit(std::type_identity<S>{}) for the registered struct S of `type`.
template <class Visit>
inline decltype(auto) visit_shape(ShapeType type, Visit&& visit) {
  switch (type) {
#define POVTRACE_SHAPE_CASE(name, Shape) \
  case ShapeType::name: return visit(std::type_identity<Shape>{});
    POVTRACE_SHAPES(POVTRACE_SHAPE_CASE)
#undef POVTRACE_SHAPE_CASE
  }
  __builtin_unreachable();   // every ShapeType is in the list it was made from
}

// The adapters: what geometry.hpp's functions do for one shape S.
template <class S>
Intersections intersections_of(const Primitive& p, const Ray& ray) {
  if constexpr (HasIntersect<S>) return S::intersect(p, ray);
  else if constexpr (HasRoots<S>) return first_roots<S>(p, ray);
  else return {};   // any number of roots: collect_hits and nearest_hit only
}

template <class S>
void collect_hits_of(const Primitive& p, const Ray& ray, HitBuffer& out) {
  if constexpr (HasCollect<S>) {
    S::collect(p, ray, out);
  } else if constexpr (HasRoots<S>) {
    collect_roots<S>(p, ray, out);
  } else {
    const Intersections xs = S::intersect(p, ray);
    for (int k = 0; k < xs.count; ++k) out.push_back(SurfaceHit{xs.t[k], &p, xs.element[k], 0, 0});
  }
}

template <class S>
std::optional<SurfaceHit> nearest_hit_of(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  if constexpr (HasCollect<S>) {
    return S::nearest(p, ray, t_min, t_max);
  } else if constexpr (HasRoots<S>) {
    return nearest_root<S>(p, ray, t_min, t_max);
  } else {
    const Intersections xs = S::intersect(p, ray);
    for (int k = 0; k < xs.count; ++k) {
      if (!(xs.t[k] > t_min)) continue;
      if (!(xs.t[k] < t_max)) return std::nullopt;   // roots are depth-sorted: the first one above t_min decides
      return SurfaceHit{xs.t[k], &p, xs.element[k], 0, 0};
    }
    return std::nullopt;
  }
}

template <class S>
Vec3 hit_normal_of(const SurfaceHit& hit, Vec3 world_point) {
  if constexpr (HasHitNormal<S>) return S::hit_normal(hit, world_point);
  else return S::normal(*hit.leaf, world_point);
}

// The hit's world point: the shape's own where its depth does not give it back (a julia_fractal's march), else
// where the ray is at that depth.
template <class S>
Vec3 hit_point_of(const Ray& ray, const SurfaceHit& hit) {
  if constexpr (HasHitPoint<S>) return S::hit_point(hit);
  else return ray.origin + ray.direction * hit.t;
}

template <class S>
bool inside_of(const Primitive& p, Vec3 world_point) {
  if constexpr (HasInside<S>) return S::inside(p, world_point);
  else return false;
}

// World bounds of an object-space box: the box of its 8 transformed corners.
inline Bounds object_to_world(const Primitive& p, const Bounds& object) {
  if (!p.transformed || object.empty()) return object;
  Bounds world;
  for (int corner = 0; corner < 8; ++corner) {
    const Vec3 c{(corner & 1) ? object.hi.x : object.lo.x, (corner & 2) ? object.hi.y : object.lo.y,
                 (corner & 4) ? object.hi.z : object.lo.z};
    world.extend(p.world_from_object.point(c));
  }
  return world;
}

template <class S>
Bounds world_bounds_of(const Primitive& p) {
  if constexpr (HasObjectBounds<S>) return object_to_world(p, S::object_bounds(p));
  else return S::world_bounds(p);
}

template <class S>
std::array<double, 2> uv_of(const SurfaceHit& hit, Vec3 world_point, double scene_scale) {
  if constexpr (HasUv<S>) return S::uv(hit, world_point);
  else return {world_point.x / scene_scale, world_point.y / scene_scale};
}

// Appends to `out` the primitive of a shape description placed by `world_from_object` (type, shape parameters, data
// and transform; material, object index and flags are the caller's, to set on the one returned), or appends nothing
// and returns nullptr when the shape renders nothing (a disc with a zero normal). Built straight into the list: a
// Primitive holds two matrices, and a copy through an optional cost the scene build 3 % of its instructions with
// 100,000 spheres. Throws std::logic_error for a description no registered shape builds (CSG).
Primitive* append_shape(const Shape& description, const Matrix& world_from_object, const BuildContext& context,
                        std::vector<Primitive>& out);

}  // namespace povtrace::render::shapes

// CSG: union, merge, intersection (difference is built as an intersection), clipped_by and bounded_by.
//
// SDL: `union|merge|intersection|difference { objects… modifiers }` and the modifiers `inverse`,
// `clipped_by { objects }`, `bounded_by { objects }` on any object (povray-sdl-and-geometry.md §9, §10). A node's
// children are render primitives of any type, CSG included; everything about them goes through the generic
// collect_hits / inside / world_bounds, so a shape added later works inside CSG unchanged.
//
// POV-Ray behaviour reproduced here (facts read from source/backend/shape/csg.cpp and scene/objects.cpp,
// 3.7-stable):
// - Union: every hit of every child is kept. Intersection: a child's hit is kept only when the hit point is inside
//   every other child. Merge: a child's hit is kept only when the point is inside no other child. The point is the
//   world point of the hit; the inside tests are the children's own (Inside_Object).
// - Inside: union and merge, inside any child; intersection, inside all children (an empty intersection is
//   inside everywhere). Lights inside CSG take no part: the parser has already moved them to the scene.
// - Difference { A B C }: B and C are inverted when parsed, then it is an intersection. Inverting a CSG inverts
//   its children and turns a union or merge into an intersection and an intersection into a merge (De Morgan);
//   the node's clip objects are not inverted. Here inversion is always pushed down to the leaves (`inverted`),
//   so a leaf's `inverse` flag is its effective orientation, which is what shading needs (tracer.cpp).
// - clipped_by: a hit survives only when its point is inside every clip object (Point_In_Clip), and the inside
//   test of the clipped object also requires every clip object (Inside_Object). Applied after the operation.
// - bounded_by: before any child is tested, for each bounding object the ray must hit it (any root at depth
//   >= MIN_ISECT_DEPTH, as Find_Intersection) or start inside it (Ray_In_Bound); otherwise the node has no hits
//   for this ray. It never changes the inside test.
// - no_image / no_reflection: a union skips the children a ray's kind does not see (Test_Ray_Flags, under which
//   camera rays still see no_image children); a merge skips them (Test_Ray_Flags_Shadow, the top-level test) both
//   for their hits and for the inside tests that remove the other children's hits; an intersection tests none.
// - Each hit keeps the child primitive it came from as `leaf`, so the child's texture and normal are used: a
//   difference's cut faces are the subtracted objects' surfaces and carry their textures.
//
// Bounds (ours, conservative: they only cull): a union or merge's surface lies within the union of its children's
// surfaces; an intersection's within the intersection of its children's extents (an extent encloses surface and
// inside; an inverted leaf's or a plane's extent is unbounded, so such children do not narrow it, as POV-Ray
// leaves inverted children out of an intersection's box); clip objects narrow both.
#include "renderer/shapes/csg.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace povtrace::render {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

Bounds everywhere() { return Bounds{{-inf, -inf, -inf}, {inf, inf, inf}}; }

Bounds intersect(const Bounds& a, const Bounds& b) { return Bounds{max(a.lo, b.lo), min(a.hi, b.hi)}; }

// Empty on any axis (Bounds::empty looks at x only, which is enough for bounds built by extend, not intersect).
bool is_empty(const Bounds& b) { return b.lo.x > b.hi.x || b.lo.y > b.hi.y || b.lo.z > b.hi.z; }

// Finite bounds grown slightly (the BVH's padding) so rounding in the leaves' own tests can never put a root
// outside them; partly infinite bounds become `everywhere`; empty stays empty.
Bounds padded_or_everywhere(const Bounds& b) {
  if (is_empty(b)) return Bounds{};
  if (!b.finite()) return everywhere();
  double magnitude = 1.0;
  for (int i = 0; i < 3; ++i) magnitude = std::max({magnitude, std::abs(b.lo[i]), std::abs(b.hi[i])});
  const double pad = magnitude * 1e-7 + 1e-9;
  const Vec3 e{pad, pad, pad};
  return Bounds{b.lo - e, b.hi + e};
}

const CsgData& csg_data(const Primitive& p) { return static_cast<const CsgData&>(*p.data); }

// Does the ray (t >= 0) pass through the finite box b?
bool ray_meets(const Bounds& b, const Ray& ray) {
  double t_near = 0, t_far = inf;
  for (int i = 0; i < 3; ++i) {
    const double inv = 1.0 / ray.direction[i];
    double t0 = (b.lo[i] - ray.origin[i]) * inv;
    double t1 = (b.hi[i] - ray.origin[i]) * inv;
    if (t0 > t1) std::swap(t0, t1);
    // NaN (origin on a slab plane of an axis the ray is parallel to) leaves the interval unchanged.
    if (t0 > t_near) t_near = t0;
    if (t1 < t_far) t_far = t1;
  }
  return t_near <= t_far;
}

// Ray_In_Bound: every bounding object is hit at depth >= MIN_ISECT_DEPTH or contains the ray's origin. The roots
// are collected past the end of `scratch` and removed again.
bool ray_in_bounds(const CsgData& d, const Ray& ray, HitBuffer& scratch) {
  for (const Primitive& bound : d.bounds) {
    const std::size_t mark = scratch.size();
    collect_hits(bound, ray, scratch);
    bool hit = false;
    for (std::size_t k = mark; k < scratch.size() && !hit; ++k) hit = scratch[k].t >= tolerance::min_isect_depth;
    scratch.resize(mark);
    if (!hit && !inside(bound, ray.origin)) return false;
  }
  return true;
}

bool inside_all(const std::vector<Primitive>& objects, Vec3 point) {
  for (const Primitive& o : objects)
    if (!inside(o, point)) return false;
  return true;
}

// Whether a ray of this kind skips `child` of a node of this operation (no_image / no_reflection): POV-Ray tests
// union children with Test_Ray_Flags (primary rays still see no_image children), merge children with
// Test_Ray_Flags_Shadow (as at the top level), and intersection children not at all.
bool skipped_child(CsgOperation operation, const Primitive& child, std::uint8_t kind) {
  if (!(child.ray_flags && kind) || operation == CsgOperation::intersection) return false;
  return ray_flag::hidden_from(child.ray_flags, operation == CsgOperation::union_) & kind;
}

// Whether a hit of child `hit_child` at `point` is part of the node's surface, for a ray of kind `kind`.
bool survives(const CsgData& d, std::size_t hit_child, Vec3 point, std::uint8_t kind) {
  if (!inside_all(d.clips, point)) return false;
  if (d.operation == CsgOperation::union_) return true;
  const bool keep_if_inside = d.operation == CsgOperation::intersection;
  for (std::size_t j = 0; j < d.children.size(); ++j) {
    if (j == hit_child) continue;
    // A merge child the ray skips does not hide the others' surfaces inside it (CSGMerge::All_Intersections).
    if (skipped_child(d.operation, d.children[j], kind)) continue;
    if (inside(d.children[j], point) != keep_if_inside) return false;
  }
  return true;
}

}  // namespace

namespace shapes {

void CsgShape::collect(const Primitive& p, const Ray& ray, HitBuffer& out) {
  const CsgData& d = csg_data(p);
  if (d.bounding_box.finite() && !ray_meets(d.bounding_box, ray)) return;
  if (!d.bounds.empty() && !ray_in_bounds(d, ray, out)) return;
  for (std::size_t i = 0; i < d.children.size(); ++i) {
    if (skipped_child(d.operation, d.children[i], ray.kind)) continue;
    const Bounds& cull = d.child_cull[i];
    if (is_empty(cull) || (cull.finite() && !ray_meets(cull, ray))) continue;
    // The child appends its roots; they are filtered in place (indices, since nested nodes may grow `out`).
    const std::size_t begin = out.size();
    collect_hits(d.children[i], ray, out);
    std::size_t kept = begin;
    for (std::size_t k = begin; k < out.size(); ++k)
      if (survives(d, i, hit_point(ray, out[k]), ray.kind)) out[kept++] = out[k];
    out.resize(kept);
  }
}

std::optional<SurfaceHit> CsgShape::nearest(const Primitive& p, const Ray& ray, double t_min, double t_max) {
  // One scratch buffer per thread, used as a stack so that nested use could never clobber an outer caller.
  thread_local HitBuffer scratch;
  const std::size_t base = scratch.size();
  collect(p, ray, scratch);
  std::optional<SurfaceHit> best;
  for (std::size_t k = base; k < scratch.size(); ++k) {
    const SurfaceHit& h = scratch[k];
    if (h.t > t_min && h.t < t_max && (!best || h.t < best->t)) best = h;
  }
  scratch.resize(base);
  return best;
}

bool CsgShape::inside(const Primitive& p, Vec3 world_point) {
  const CsgData& d = csg_data(p);
  if (!inside_all(d.clips, world_point)) return false;
  if (d.operation == CsgOperation::intersection) return inside_all(d.children, world_point);
  for (const Primitive& child : d.children)
    if (render::inside(child, world_point)) return true;
  return false;
}

Bounds CsgShape::world_bounds(const Primitive& p) {
  const CsgData& d = csg_data(p);
  // No surface can survive: a point box keeps the node in the BVH rather than in the list every ray tests.
  if (is_empty(d.surface)) return Bounds{{0, 0, 0}, {0, 0, 0}};
  return d.surface;
}

Vec3 CsgShape::normal(const Primitive&, Vec3) {
  throw std::logic_error("a CSG node has no surface of its own: its hits carry the child primitive as leaf");
}

}  // namespace shapes

Bounds solid_extent(const Primitive& p) {
  if (p.type == ShapeType::csg) return csg_data(p).extent;
  // A height field's inside goes on below its bottom (HField::Inside: under the water level is inside), so an
  // object clipped by one keeps its surface there.
  if (p.inverse || p.type == ShapeType::height_field) return everywhere();
  return padded_or_everywhere(world_bounds(p));
}

Primitive make_csg(CsgOperation operation, std::vector<Primitive> children, std::vector<Primitive> clips,
                   std::vector<Primitive> bounds) {
  auto d = std::make_shared<CsgData>();
  d->operation = operation;
  d->children = std::move(children);
  d->clips = std::move(clips);
  d->bounds = std::move(bounds);
  Bounds children_surface;
  Bounds extent = operation == CsgOperation::intersection ? everywhere() : Bounds{};
  for (const Primitive& child : d->children) {
    const Bounds surface = child.type == ShapeType::csg ? csg_data(child).surface
                                                        : padded_or_everywhere(world_bounds(child));
    d->child_cull.push_back(surface);
    children_surface.extend(surface);
    if (operation == CsgOperation::intersection) extent = intersect(extent, solid_extent(child));
    else extent.extend(solid_extent(child));
  }
  Bounds surface = operation == CsgOperation::intersection ? intersect(children_surface, extent) : children_surface;
  d->unclipped_surface = surface;
  for (const Primitive& clip : d->clips) {
    surface = intersect(surface, solid_extent(clip));
    extent = intersect(extent, solid_extent(clip));
  }
  d->surface = is_empty(surface) ? Bounds{} : surface;
  d->extent = is_empty(extent) ? Bounds{} : extent;
  Primitive p;
  p.type = ShapeType::csg;
  p.data = std::move(d);
  return p;
}

double volume(const Bounds& b) {
  if (is_empty(b)) return 0;
  if (!b.finite()) return inf;
  const Vec3 e = b.hi - b.lo;
  return e.x * e.y * e.z;
}

// Parse_Object_Mods: the box of the bounding objects (inverted ones left out) replaces the object's box when its
// volume is smaller; the node then lies in the BVH with that box and rays missing it miss the node. POV-Ray does
// the same with the clipping objects next, on the box the bounds left.
// The box POV-Ray gives a set of bounding or clipping objects: the intersection of their boxes (each one's own,
// unpadded), inverted ones left out.
Bounds box_of_objects(const std::vector<Primitive>& objects) {
  Bounds box = everywhere();
  for (const Primitive& b : objects)
    if (b.type == ShapeType::csg) box = intersect(box, csg_data(b).extent);
    else if (!b.inverse) box = intersect(box, world_bounds(b));
  return box;
}

Primitive with_bounding_box_from(const Primitive& node, const std::vector<Primitive>& bounding_objects) {
  const Bounds box = box_of_objects(bounding_objects);
  const CsgData& d = csg_data(node);
  if (!box.finite() || is_empty(box) || !(volume(box) < volume(d.surface))) return node;
  auto copy = std::make_shared<CsgData>(d);
  copy->bounding_box = box;
  copy->surface = intersect(d.surface, box);
  if (is_empty(copy->surface)) copy->surface = Bounds{};
  Primitive p = node;
  p.data = std::move(copy);
  return p;
}

Primitive with_clipping_box_from(const Primitive& node, const std::vector<Primitive>& clips) {
  const CsgData& d = csg_data(node);
  // The object's box before its clips: the one bounded_by gave it, else its children's.
  const Bounds& own_box = d.bounding_box.finite() ? d.bounding_box : d.unclipped_surface;
  const Bounds box = box_of_objects(clips);
  if (!box.finite() || is_empty(box) || !(volume(box) < volume(own_box))) return node;
  auto copy = std::make_shared<CsgData>(d);
  copy->bounding_box = box;
  Primitive p = node;
  p.data = std::move(copy);
  return p;
}

Primitive with_culling_box(const Primitive& node, const std::optional<Bounds>& box) {
  auto copy = std::make_shared<CsgData>(csg_data(node));
  copy->bounding_box = box ? *box : Bounds{};
  Primitive p = node;
  p.data = std::move(copy);
  return p;
}

Primitive inverted(const Primitive& p) {
  if (p.type != ShapeType::csg) {
    Primitive q = p;
    q.inverse = !q.inverse;
    return q;
  }
  const CsgData& d = csg_data(p);
  std::vector<Primitive> children;
  children.reserve(d.children.size());
  for (const Primitive& child : d.children) children.push_back(inverted(child));
  const CsgOperation op =
      d.operation == CsgOperation::intersection ? CsgOperation::merge : CsgOperation::intersection;
  Primitive q = make_csg(op, std::move(children), d.clips, d.bounds);
  q.material = p.material;
  q.object = p.object;
  q.casts_shadow = p.casts_shadow;
  q.ray_flags = p.ray_flags;
  q.hidden_from = p.hidden_from;
  return q;
}

}  // namespace povtrace::render

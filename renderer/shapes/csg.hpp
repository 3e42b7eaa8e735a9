// CSG nodes as render primitives (ShapeType::csg): the out-of-line data a CSG primitive carries and how to build
// one. Everything else about a CSG (hits, inside, bounds) goes through the generic interface of geometry.hpp, which
// dispatches to renderer/shapes/csg.cpp. The render-scene builder and the tests construct nodes with these.
#pragma once

#include <optional>
#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"

namespace povtrace::render {

// A difference is an intersection whose later children are inverted (built that way), so three operations remain.
enum class CsgOperation : std::uint8_t {
  union_,         // every child hit is kept; inside any child
  merge,          // a child hit is kept when not inside any other child; inside any child
  intersection,   // a child hit is kept when inside every other child; inside all children
};

struct CsgData final : ShapeData {
  CsgOperation operation = CsgOperation::union_;
  std::vector<Primitive> children;   // any shape, CSG included; inversion already pushed down to the leaves
  std::vector<Primitive> clips;      // clipped_by: hits and inside points must be inside all of these
  std::vector<Primitive> bounds;     // bounded_by: a ray that misses one of these (and starts outside it) sees nothing
  // POV-Ray's bounding box taken from bounding objects (also from those removed when the object was placed): a
  // ray that does not meet it sees nothing of the node. Not finite: no such box.
  Bounds bounding_box;
  // Derived by make_csg:
  std::vector<Bounds> child_cull;    // each child's padded surface bounds (empty Bounds = never culled)
  Bounds surface;                    // where surviving hits can be (world_bounds of the node)
  Bounds unclipped_surface;          // the same before the clips (what POV-Ray weighs their box against)
  Bounds extent;                     // encloses the surface and the inside region (non-finite if unbounded)
};

// A CSG primitive over `children`, clipped and bounded as given, with its bounds computed. Material, object index
// and shadow flag are the caller's to set. Children are stored in the node: hits' `leaf` points into it.
Primitive make_csg(CsgOperation operation, std::vector<Primitive> children, std::vector<Primitive> clips = {},
                   std::vector<Primitive> bounds = {});

// `node` (from make_csg) with the bounding box that bounding objects give it in POV-Ray: the intersection of the
// boxes of the non-inverted ones, taken only when its volume is smaller than the node's own box.
Primitive with_bounding_box_from(const Primitive& node, const std::vector<Primitive>& bounding_objects);

// `node` with the bounding box its clipping objects give it in POV-Ray (Parse_Object_Mods, after the bounding
// objects): the intersection of the non-inverted clips' boxes, taken when its volume is smaller than the object's
// box before the clips (its children's, or the one bounded_by gave it). Rays that miss that box see nothing of the
// node; the surface bounds stay as they are, since a clip's inside can reach beyond its box.
Primitive with_clipping_box_from(const Primitive& node, const std::vector<Primitive>& clips);

// `node` tested only for rays that meet `box` (POV-Ray's bounding box of the clipped object, which can be tighter
// than its clips' box); with no box (POV-Ray's huge one), for every ray. Surface bounds stay as they are.
Primitive with_culling_box(const Primitive& node, const std::optional<Bounds>& box);

// `p` with inside and outside swapped. A leaf toggles its `inverse` flag; a CSG node follows De Morgan as POV-Ray
// does (children inverted; union and merge become intersection, intersection becomes merge; clips and bounds stay).
Primitive inverted(const Primitive& p);

// Bounds that enclose both the surface of `p` and its inside region: non-finite for inverted leaves and planes.
Bounds solid_extent(const Primitive& p);

}  // namespace povtrace::render

namespace povtrace::render::shapes {

// CSG nodes (csg.cpp): hits come from the children through collect_hits, so there is no intersect; a node has no
// surface of its own (its hits carry the child as leaf). Built by renderer/csg_build.cpp from the description
// (it needs the materials of the children), so there is no build here.
struct CsgShape {
  using Description = Csg;
  static void collect(const Primitive& p, const Ray& ray, HitBuffer& out);   // appends every hit
  static std::optional<SurfaceHit> nearest(const Primitive& p, const Ray& ray, double t_min, double t_max);
  static Vec3 normal(const Primitive& p, Vec3 world_point);
  static bool inside(const Primitive& p, Vec3 world_point);
  static Bounds world_bounds(const Primitive& p);
};

}  // namespace povtrace::render::shapes

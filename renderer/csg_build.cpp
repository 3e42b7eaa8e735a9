// Building CSG render nodes from description objects (see csg_build.hpp). Inversion is already pushed down to
// the leaves by the parser (De Morgan, and a difference's later children); a `difference` built in code is
// handled the same way here.
#include "renderer/csg_build.hpp"

#include "renderer/shapes/csg.hpp"

namespace povtrace::render {

namespace {

CsgOperation operation_of(CsgKind kind) {
  switch (kind) {
    case CsgKind::union_: return CsgOperation::union_;
    case CsgKind::merge: return CsgOperation::merge;
    case CsgKind::intersection:
    case CsgKind::difference: return CsgOperation::intersection;
  }
  return CsgOperation::union_;
}

// `placed`: the build's context when the object is placed in the scene itself, null inside a CSG.
Primitive node_for(const Object& o, bool shaded, const LeafBuilder& add_leaf, const BuildContext* placed);

// The box POV-Ray culls the rays of an object placed in the scene with (its bounding slabs test each object's box):
// the box the parser made when it placed the object (Object::placed_box). It shows where the object's surface
// reaches beyond its box: a quadric clipped by a height field keeps the quadric's own box within the clip's, where
// the clip's box alone would let rays through that POV-Ray never tests; a merge or an intersection holding such a
// child keeps its own box. Objects inside a CSG are not culled by their boxes (CSGUnion::All_Intersections tests
// only their bounded_by).
struct CullingBox {
  bool known = false;       // false: the parser cannot make the box (the clips' box is used instead)
  std::optional<Bounds> box;   // empty: POV-Ray's huge box, nothing is culled
};

CullingBox povray_culling_box(const Object& o) {
  if (!o.placed_box || !o.placed_box->known) return {};
  const ExtentBox& b = o.placed_box->box;
  for (int i = 0; i < 3; ++i)
    if (!(b.lengths[i] < kBoundHuge / 2)) return {true, std::nullopt};
  return {true, Bounds{b.lo(), b.hi()}};
}

// One primitive for any object: its node, its single leaf primitive, or a union of its leaf primitives.
Primitive primitive_for(const Object& o, bool shaded, const LeafBuilder& add_leaf) {
  if (needs_csg_node(o)) return node_for(o, shaded, add_leaf, nullptr);
  std::vector<Primitive> leaves;
  add_leaf(o, shaded, leaves);
  for (Primitive& leaf : leaves) leaf.csg_child = true;
  if (leaves.size() == 1) return leaves.front();
  return make_csg(CsgOperation::union_, std::move(leaves));
}

std::vector<Primitive> primitives_for(const std::vector<Object>& objects, bool shaded, const LeafBuilder& add_leaf) {
  std::vector<Primitive> out;
  out.reserve(objects.size());
  for (const Object& o : objects) out.push_back(primitive_for(o, shaded, add_leaf));
  return out;
}

Primitive node_for(const Object& o, bool shaded, const LeafBuilder& add_leaf, const BuildContext* placed) {
  CsgOperation operation = CsgOperation::union_;
  std::vector<Primitive> children;
  if (const auto* csg = std::get_if<Csg>(&o.shape)) {
    operation = operation_of(csg->kind);
    children = primitives_for(csg->children, shaded, add_leaf);
    if (csg->kind == CsgKind::difference)
      for (std::size_t i = 1; i < children.size(); ++i) children[i] = inverted(children[i]);
  } else {
    add_leaf(o, shaded, children);   // a clipped or bounded shape: a one-child union carrying the clip or bound
    for (Primitive& leaf : children) leaf.csg_child = true;
  }
  std::vector<Primitive> bounds = primitives_for(o.bounded_by, false, add_leaf);
  const std::vector<Primitive> clips = primitives_for(o.clipped_by, false, add_leaf);
  Primitive p = make_csg(operation, std::move(children), clips, bounds);
  // Bounds removed when the object was placed still gave it their bounding box (csg_modifiers.cpp).
  for (Primitive& removed : primitives_for(o.removed_bounds, false, add_leaf)) bounds.push_back(std::move(removed));
  if (!bounds.empty()) p = with_bounding_box_from(p, bounds);
  // Then the clipping objects' box (Parse_Object_Mods): rays that miss it see nothing of the object, even where the
  // clip's inside reaches beyond its box (a height field's inside goes on below its bottom).
  if (placed) {
    const CullingBox culling = povray_culling_box(o);
    if (culling.known) p = with_culling_box(p, culling.box);
    else if (!clips.empty()) p = with_clipping_box_from(p, clips);
  }
  p.casts_shadow = !o.no_shadow;
  set_ray_flags(p, o);
  return p;
}

// Link_To_Frame: a union all of whose children have no_shadow gets no_shadow too.
bool all_children_without_shadow(const Csg& csg) {
  for (const Object& child : csg.children)
    if (!child.no_shadow) return false;
  return true;
}

}  // namespace

void set_ray_flags(Primitive& p, const Object& o) {
  p.ray_flags = static_cast<std::uint8_t>((o.no_image ? ray_flag::no_image : 0) |
                                          (o.no_reflection ? ray_flag::no_reflection : 0) |
                                          (o.no_radiosity ? ray_flag::no_radiosity : 0));
  p.hidden_from = ray_flag::hidden_from(p.ray_flags, false);
}

bool splits_into_children(const Object& o) {
  const auto* csg = std::get_if<Csg>(&o.shape);
  return csg && csg->kind == CsgKind::union_ && o.clipped_by.empty() && o.bounded_by.empty();
}

bool needs_csg_node(const Object& o) {
  return std::holds_alternative<Csg>(o.shape) || !o.clipped_by.empty() || !o.bounded_by.empty() ||
         !o.removed_bounds.empty();
}

Primitive build_csg_node(const Object& o, const LeafBuilder& add_leaf, const BuildContext& context) {
  Primitive p = node_for(o, true, add_leaf, &context);
  if (const auto* csg = std::get_if<Csg>(&o.shape); csg && csg->kind == CsgKind::union_ && all_children_without_shadow(*csg))
    p.casts_shadow = false;
  return p;
}

}  // namespace povtrace::render

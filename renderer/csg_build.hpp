// Description objects that become CSG render nodes (renderer/shapes/csg.hpp): every union, merge and
// intersection except the unions POV-Ray splits into their children, and any object with clipped_by or
// bounded_by. The shapes themselves are turned into primitives by the caller (render_scene.cpp), so a shape added
// there works inside CSG, clips and bounds without changes here.
#pragma once

#include <functional>
#include <vector>

#include "scene/description.hpp"
#include "renderer/geometry.hpp"
#include "renderer/object_primitives.hpp"

namespace povtrace::render {

// Appends the primitives of one non-CSG object without clip or bound. `shaded` is false for clip and bounding
// objects, which are never shaded and have no texture.
using LeafBuilder = std::function<void(const Object& leaf, bool shaded, std::vector<Primitive>& out)>;

// A top-level union without clipped_by or bounded_by is placed as its children (POV-Ray's split_union: each child
// becomes a scene object of its own; a bounded union stays whole since Split_Unions is off by default).
bool splits_into_children(const Object& o);

// Gives `p` the object's no_image / no_reflection (Primitive::ray_flags) and the top-level test of them
// (Primitive::hidden_from). A split union's children are top-level objects in POV-Ray (Link_To_Frame), each tested
// with its own flags, which already include the union's (the parser's post_process).
void set_ray_flags(Primitive& p, const Object& o);

// Whether the object needs a CSG node: it is CSG (and not split) or has clip or bounding objects.
bool needs_csg_node(const Object& o);

// The node for `o` (needs_csg_node(o)), with its children, clips and bounds built recursively. Its casts_shadow
// follows the object's no_shadow (and POV-Ray's rule that a union whose children all have no_shadow has it too);
// material and object index are left to the caller. `context` gives the box POV-Ray culls the node's rays with.
Primitive build_csg_node(const Object& o, const LeafBuilder& add_leaf, const BuildContext& context);

}  // namespace povtrace::render

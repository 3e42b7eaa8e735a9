// One description object (a shape without CSG, clip or bound) as world-space primitives: what the render-ready
// scene (render_scene.cpp) and the parse-time geometry of trace() (object_geometry.cpp) both build from.
#pragma once

#include <cstdint>
#include <vector>

#include "scene/description.hpp"
#include "scene/object_geometry.hpp"
#include "renderer/build_context.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shared_meshes.hpp"

namespace povtrace::render {

// Appends the object's primitive (none for a disc with a zero normal, which POV-Ray does not render either), with
// the given material and top-level object index. CSG objects go through build_csg_node (csg_build.hpp) instead.
void add_shape_primitives(const Object& o, std::uint32_t material, std::uint32_t object_index,
                          const BuildContext& context, std::vector<Primitive>& out);

}  // namespace povtrace::render

// POV-Ray's box of each object placed in the scene (Object::placed_box), which the renderer culls its rays with.
#pragma once

#include "parser/extents/object_extents.hpp"

namespace povtrace::sdl {

// Sets the box on an object as it is placed and, since POV-Ray places the children of a union without clip and
// bounding objects one by one (Link_To_Frame splits it; so does the renderer, render_scene.cpp add_object), on those
// children in turn.
void set_placed_boxes(Object& o, const ObjectExtents& extents);

// Whether set_placed_boxes gives the object a box: only objects the renderer culls by it (CSG, and objects with
// clip, bounding or removed bounding objects).
bool culled_by_placed_box(const Object& o);

}  // namespace povtrace::sdl

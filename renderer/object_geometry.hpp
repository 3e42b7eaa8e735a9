// The renderer's side of the parse-time geometry queries (scene/object_geometry.hpp): trace() and inside() on a
// declared object, answered by the same primitives, CSG nodes and intersection code that render the scene.
#pragma once

#include <memory>

#include "scene/object_geometry.hpp"

namespace povtrace::render {

// The implementation to hand the parser in ParseOptions::object_geometry. Shareable between threads; it remembers
// the extents of the height-field images it has read (per file, modification time and water level).
std::shared_ptr<const ObjectGeometry> object_geometry();

}  // namespace povtrace::render

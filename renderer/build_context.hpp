// What building primitives reads besides the description objects (object_primitives.hpp, csg_build.hpp and the
// shapes' build functions, shapes/shape_registry.hpp), for one scene build or one parse-time geometry query.
#pragma once

namespace povtrace {
class ObjectGeometry;
}

namespace povtrace::render {

class SharedMeshes;

struct BuildContext {
  // The scene's noise generator (1, 2 or 3) as functions read it: isosurfaces' and those in a height field's
  // pigment function. A render passes global_settings' (as the scene ends), a parse-time query the one in force.
  int noise_generator;
  SharedMeshes& meshes;             // one BVH per mesh, whatever its placements (shared_meshes.hpp)
  const ObjectGeometry& geometry;   // height-field extents for POV-Ray's boxes of placed CSG (csg_build.cpp)
};

}  // namespace povtrace::render

// Ray-object geometry the SDL needs at parse time: trace(O, Start, Dir [, Normal]), inside(O, P) of shapes whose
// inside test the parser does not carry itself (object_queries.cpp), and the samples behind a height field's
// bounding box (parser/extents/object_extents.cpp). Intersecting objects is the renderer's work,
// and the parser never includes renderer code: it asks through this interface, which the program hands it in
// ParseOptions::object_geometry (renderer/object_geometry.hpp implements it). Without one, trace() is refused by
// name.
#pragma once

#include <memory>
#include <optional>

#include "scene/description.hpp"

namespace povtrace {

// Where a traced ray met the object: the intersection point and the surface's raw normal there (no normal
// perturbation, not turned toward the ray), reversed when the surface hit belongs to an inverted object, as
// POV-Ray's Parse_Trace returns them.
struct TracedHit {
  Vec3 point;
  Vec3 normal;
};

// One declared object made ready for repeated queries (scenes call trace() in loops on the same object).
class PreparedObject {
 public:
  virtual ~PreparedObject() = default;
  // POV-Ray's Find_Intersection on this object alone: the nearest intersection at a depth of at least
  // MIN_ISECT_DEPTH along origin + t·direction, `direction` of unit length; nothing on a miss.
  virtual std::optional<TracedHit> trace(Vec3 origin, Vec3 unit_direction) const = 0;
  // POV-Ray's Inside_Object.
  virtual bool inside(Vec3 point) const = 0;
};

// A height field's sample grid and its bounding box's y range in sample units, as POV-Ray's Compute_HField makes
// them: from the lowest sample (or the water level, if higher) less 0.001 to the highest sample plus 0.001.
struct HeightFieldExtent {
  int width = 0, depth = 0;
  double bottom = 0, top = 0;
};

class ObjectGeometry {
 public:
  virtual ~ObjectGeometry() = default;
  // The height field's samples read as for rendering (its image, or its pigment function sampled).
  // `noise_generator` is the scene's in force (1, 2 or 3), which functions in a pigment function read.
  virtual HeightFieldExtent height_field_extent(const HeightField& h, int noise_generator) const = 0;
  // The object as placed (its transforms composed, CSG children inverted as POV-Ray inverts them). The object
  // carries no unsupported geometry (the caller refuses those by name first). Its functions (isosurfaces) read
  // `noise_generator`, the scene's in force: prepare again when it changes.
  virtual std::unique_ptr<const PreparedObject> prepare(const Object& object, int noise_generator) const = 0;
};

}  // namespace povtrace

// POV-Ray's bounding boxes of objects as the SDL reads them with min_extent() and max_extent()
// (povray-sdl-and-geometry.md §5), made, carried and narrowed as POV-Ray 3.7 does it at parse time.
#pragma once

#include <optional>
#include <stdexcept>

#include "parser/extents/object_notes.hpp"
#include "scene/description.hpp"
#include "scene/object_geometry.hpp"

namespace povtrace::sdl {

// A box the parser cannot make without the renderer's geometry (a height field's image); the message names it.
struct ExtentUnavailable : std::runtime_error {
  explicit ExtentUnavailable(ExtentGap g) : std::runtime_error(extent_gap_name(g)), gap(g) {}
  ExtentGap gap;
};

class ObjectExtents {
 public:
  // `noise_generator`: the scene's in force, for height fields made from pigment functions (ObjectGeometry);
  // `notes`: where the boxes it carries on objects are kept (ObjectNotes), which must outlive this.
  ObjectExtents(const ObjectGeometry* geometry, int noise_generator, const NotesPool& notes)
      : geometry_(geometry), noise_generator_(noise_generator), notes_(notes) {}

  // The object's box as POV-Ray holds it now. Throws ExtentUnavailable.
  ExtentBox box(const Object& o) const;

  // Compute_BBox when the object is made (before its modifiers; a blob's after them), for the shapes whose box each
  // later transform carries (ObjectNotes::carried_extent). When the box cannot be made, records why (extent_gap).
  void made(Object& o) const;

  // The end of an object's modifiers (Parse_Object_Mods): its bounding, then its clip objects narrow a carried
  // box when their common box is smaller.
  void modifiers_ended(Object& o) const;

  // clipped_by on a quadric (Parse_Object_Mods recomputes its box with its current coefficients, within its clips).
  void quadric_clipped(Object& o) const;

  // The box of an object as it is placed in the scene (Object::placed_box), which the renderer culls its rays with.
  PlacedBox placed(const Object& o) const;

 private:
  ExtentBox shape_box(const Object& o) const;
  ExtentBox csg_box(Object& o) const;
  ExtentBox height_field_box(const Object& o, const HeightField& h) const;
  ExtentBox narrowed(const Object& o, ExtentBox box) const;
  std::optional<ExtentBox> moved_box(const Object& o) const;
  void recompute_quadric(Object& q, Vec3 clip_lo, Vec3 clip_hi) const;

  const ObjectGeometry* geometry_;
  int noise_generator_;
  const NotesPool& notes_;
};

}  // namespace povtrace::sdl

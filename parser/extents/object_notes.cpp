#include "parser/extents/object_notes.hpp"

#include <memory>

namespace povtrace::sdl {

const char* extent_gap_name(ExtentGap gap) {
  switch (gap) {
    case ExtentGap::none: break;
    case ExtentGap::height_field_samples: return "a height_field (its samples are read by the renderer)";
  }
  return "an object whose box is unknown";
}

const ObjectNotes& notes_of(const Object& o) {
  static const ObjectNotes kNone;
  return o.parser_notes ? *o.parser_notes : kNone;
}

// Copies of an object (every `object { S … }` of a declared S) share its notes until one of them changes: most
// copies change none, and copying the notes with every copy would cost an allocation each.
ObjectNotes& edit_notes(Object& o) {
  if (o.parser_notes && o.parser_notes.use_count() == 1) {
    // Only this object refers to the notes, and every ObjectNotes is made non-const (below), so writing through the
    // const pointer is defined and no one else sees the change. The parser runs on one thread, so the count holds.
    return const_cast<ObjectNotes&>(*o.parser_notes);
  }
  auto own = o.parser_notes ? std::make_shared<ObjectNotes>(*o.parser_notes) : std::make_shared<ObjectNotes>();
  ObjectNotes& notes = *own;
  o.parser_notes = std::move(own);
  return notes;
}

void clear_notes(Object& o) {
  o.parser_notes.reset();
  for (auto* list : {&o.clipped_by, &o.bounded_by, &o.removed_bounds})
    for (Object& inner : *list) clear_notes(inner);
  if (auto* csg = std::get_if<Csg>(&o.shape)) {
    for (Object& child : csg->children) clear_notes(child);
    for (Light& light : csg->lights)
      for (Object& shown : light.looks_like) clear_notes(shown);
  }
}

}  // namespace povtrace::sdl

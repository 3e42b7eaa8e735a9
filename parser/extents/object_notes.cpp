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

struct NotesPool::Blocks {
  union Block {
    Block* next;
    alignas(std::max_align_t) std::byte bytes[block_bytes];
  };
  static constexpr std::size_t blocks_per_chunk = 256;
  std::vector<std::unique_ptr<Block[]>> chunks;
  std::size_t used_in_last = blocks_per_chunk;
  Block* free = nullptr;
};

NotesPool::NotesPool() : blocks_(std::make_shared<Blocks>()) {}

void* NotesPool::take(std::size_t bytes, std::size_t alignment) {
  if (bytes > block_bytes || alignment > alignof(std::max_align_t)) return nullptr;
  Blocks& b = *blocks_;
  if (Blocks::Block* block = b.free) {
    b.free = block->next;
    return block;
  }
  if (b.used_in_last == Blocks::blocks_per_chunk) {
    b.chunks.push_back(std::make_unique_for_overwrite<Blocks::Block[]>(Blocks::blocks_per_chunk));
    b.used_in_last = 0;
  }
  return &b.chunks.back()[b.used_in_last++];
}

void NotesPool::give_back(void* block) {
  auto* freed = static_cast<Blocks::Block*>(block);
  freed->next = blocks_->free;
  blocks_->free = freed;
}

// Copies of an object (every `object { S … }` of a declared S) share its notes until one of them changes: most
// copies change none, and copying the notes with every copy would cost an allocation each.
ObjectNotes& edit_notes(Object& o, const NotesPool& pool) {
  if (o.parser_notes && o.parser_notes.use_count() == 1) {
    // Only this object refers to the notes, and every ObjectNotes is made non-const (below), so writing through the
    // const pointer is defined and no one else sees the change. The parser runs on one thread, so the count holds.
    return const_cast<ObjectNotes&>(*o.parser_notes);
  }
  const NotesAllocator<ObjectNotes> allocator(pool);
  auto own = o.parser_notes ? std::allocate_shared<ObjectNotes>(allocator, *o.parser_notes)
                            : std::allocate_shared<ObjectNotes>(allocator);
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

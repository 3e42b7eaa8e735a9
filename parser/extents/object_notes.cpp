#include "parser/extents/object_notes.hpp"

#include <cstddef>
#include <memory>
#include <vector>

namespace povtrace::sdl {

const char* extent_gap_name(ExtentGap gap) {
  switch (gap) {
    case ExtentGap::none: break;
    case ExtentGap::height_field_samples: return "a height_field (its samples are read by the renderer)";
  }
  return "an object whose box is unknown";
}

class NotesPool::Blocks {
 public:
  union Block {
    Block* next;
    alignas(std::max_align_t) std::byte bytes[block_bytes];
  };
  static constexpr std::size_t blocks_per_chunk = 256;
  std::vector<std::unique_ptr<Block[]>> chunks;
  std::size_t used_in_last = blocks_per_chunk;
  Block* free = nullptr;
  std::size_t out = 0;       // blocks taken and not given back
  bool pool_gone = false;    // then the last block given back deletes these
};

NotesPool::NotesPool() : blocks_(new Blocks) {}

NotesPool::~NotesPool() {
  if (blocks_->out == 0) delete blocks_;
  else blocks_->pool_gone = true;
}

void* NotesPool::take(Blocks& b) {
  ++b.out;
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

void NotesPool::give_back(Blocks& b, void* block) {
  auto* freed = static_cast<Blocks::Block*>(block);
  freed->next = b.free;
  b.free = freed;
  if (--b.out == 0 && b.pool_gone) delete &b;
}

// Copies of an object (every `object { S … }` of a declared S) share its notes until one of them changes: most
// copies change none, and copying the notes with every copy would cost an allocation each.
ObjectNotes& edit_notes(Object& o, const NotesPool& pool) {
  if (o.parser_notes && o.parser_notes.use_count() == 1) {
    // Only this object refers to the notes, and every ObjectNotes is made non-const (below), so writing through the
    // const pointer is defined and no one else sees the change. The parser runs on one thread, so the count holds.
    return const_cast<ObjectNotes&>(*o.parser_notes);
  }
  const NotesAllocator<ObjectNotes> allocator(pool.blocks());
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

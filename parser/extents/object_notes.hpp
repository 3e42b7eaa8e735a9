// What the parser keeps on an object while it is being built and may still be moved, queried (min_extent,
// max_extent) or edited, and which the renderer never reads: the state of POV-Ray's bounding box of the object as
// its parser holds it. Hung on the object as Object::parser_notes (opaque to scene/ and the renderer), shared by
// copies of the object until one of them changes (edit_notes), and dropped when the object is placed in the scene
// (clear_notes): a SceneDescription returned by the parser holds none.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "scene/description.hpp"

namespace povtrace::sdl {

// What keeps the parser from making a box POV-Ray would have: named in the refusal of min_extent()/max_extent().
enum class ExtentGap : std::uint8_t {
  none,
  height_field_samples,    // a height field's samples, which only the renderer reads
};
const char* extent_gap_name(ExtentGap gap);

// A sphere POV-Ray has made an ellipsoid (Sphere::Transform, Do_Ellipsoid): the centre and radius it held when the
// sphere became one, and the transforms since, from which its bounding box is made (Sphere::Compute_BBox).
struct SphereEllipsoidFrame {
  Vec3 centre;
  double radius = 1;
  Matrix since;
};
// A plane a matrix or transform block has reached, which POV-Ray then keeps as a transform instead of moving its
// normal and distance (Plane::Transform): the world unit normal and distance the plane had then, and the transforms
// since (for its bounds in an intersection or as a quadric's clip).
struct PlaneMatrixFrame {
  Vec3 normal;
  double distance = 0;
  Matrix since;
};

struct ObjectNotes {
  // The transforms not applied to the object's texture because they cannot change how it renders
  // (texture_ignores_transforms: plain layers of solid pigments, no normals), composed in written order. So copies
  // of one declared object moved by `translate` share its texture instead of copying it each. Applied if the texture
  // is edited later (an object-level pigment starts from the moved one, as POV-Ray's does); dropped when the object
  // is placed. One matrix, not a list: 100,000 moved copies made and kept a list each.
  std::optional<Matrix> deferred_texture_transform;
  // The bounding box of the shapes whose box POV-Ray carries through each later transform (Recompute_BBox of the
  // box itself — CSG::Transform, Quadric::Transform, Blob::Transform, Mesh::Transform; a text is a CSG union):
  // made with the object, then transformed, clipped and bounded as POV-Ray does, for min_extent()/max_extent().
  // Unset for the other shapes, whose box follows from the shape and world_from_object (object_queries.cpp), and
  // for a CSG whose box needs data only the renderer reads (a height field's image) when the parser has none.
  std::optional<ExtentBox> carried_extent;
  // Why carried_extent could not be made (then unset for good: later boxes hang on it).
  ExtentGap extent_gap = ExtentGap::none;
  // A transform reached the object since its modifiers last ended: POV-Ray then holds the box its shape gives,
  // without the narrowing by clip and bounding objects that the end of Parse_Object_Mods applies (a parent's or a
  // clipped_by list's transforms; a height field's box, made after its own modifiers). Only the shapes whose box
  // is remade from the shape read it.
  bool box_skips_clips = false;
  // Held by value: copies of the object share the notes themselves.
  std::optional<SphereEllipsoidFrame> ellipsoid_frame;   // a sphere, once POV-Ray made it an ellipsoid
  std::optional<PlaneMatrixFrame> matrix_frame;          // a plane, once a matrix or transform block reached it
  // A poly: POV-Ray's Poly::Compute_BBox, run when the poly is made and at each transform, takes the first clip
  // object's box (else the huge box): set once a transform has met a clipped poly.
  bool box_from_first_clip = false;
  // A quadric: POV-Ray's Automatic_Bounds, set once its box computation used the box it found (every quadric without
  // a mixed term, when parsed): a placed quadric then loses its bounded_by like most shapes.
  bool automatic_bounds = false;
};

// Where the notes of one parse are made: fixed-size blocks kept on a free list. In bench's parse_objects each of
// 100,000 moved copies of a declared object gets notes (its deferred texture transform) and drops them when placed;
// malloc and free of each cost more than everything else the notes do. The pool belongs to the parse; its blocks
// stay until the pool is gone and every block is back, since notes may outlive the parse (a copy of an object taken
// in ParseOptions::placing). One thread only, as the parser.
class NotesPool {
 public:
  class Blocks;   // what the notes' allocators refer to

  NotesPool();
  ~NotesPool();
  NotesPool(const NotesPool&) = delete;
  NotesPool& operator=(const NotesPool&) = delete;

  Blocks& blocks() const { return *blocks_; }

  static constexpr std::size_t block_bytes = 640;
  // Whether a T fits a block: else it comes from operator new.
  template <class T>
  static constexpr bool fits = sizeof(T) <= block_bytes && alignof(T) <= alignof(std::max_align_t);
  static void* take(Blocks& blocks);
  static void give_back(Blocks& blocks, void* block);

 private:
  Blocks* blocks_;
};

// The allocator of the notes' shared_ptr control blocks (std::allocate_shared): blocks from the pool, and
// construction without the zeroing that value-initialisation does first (ObjectNotes has member initialisers).
template <class T>
struct NotesAllocator {
  using value_type = T;
  explicit NotesAllocator(NotesPool::Blocks& b) : blocks(&b) {}
  template <class U>
  NotesAllocator(const NotesAllocator<U>& other) : blocks(other.blocks) {}   // NOLINT: rebinding, as allocators do

  T* allocate(std::size_t n) {
    if (n == 1 && NotesPool::fits<T>) return static_cast<T*>(NotesPool::take(*blocks));
    return std::allocator<T>{}.allocate(n);
  }
  void deallocate(T* p, std::size_t n) {
    if (n == 1 && NotesPool::fits<T>) NotesPool::give_back(*blocks, p);
    else std::allocator<T>{}.deallocate(p, n);
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args) {
    if constexpr (sizeof...(Args) == 0) ::new (static_cast<void*>(p)) U;
    else ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
  template <class U>
  friend bool operator==(const NotesAllocator& a, const NotesAllocator<U>& b) { return a.blocks == b.blocks; }

  NotesPool::Blocks* blocks;
};

// The object's notes; an object without any reads as the defaults (nothing carried, no gap, nothing skipped).
inline const ObjectNotes& notes_of(const Object& o) {
  static constexpr ObjectNotes none{};
  return o.parser_notes ? *o.parser_notes : none;
}

// The object's own notes to change: made from the pool when it has none, copied first when copies of the object
// share them (so that changing one copy's notes leaves the others' alone).
ObjectNotes& edit_notes(Object& o, const NotesPool& pool);

// Drops the notes of the object and of every object inside it (clip and bounding objects, removed bounds, CSG
// children, the looks_like objects of lights inside): called when the object is placed, edited no more.
void clear_notes(Object& o);

}  // namespace povtrace::sdl

// The interiors a ray is travelling through, innermost (most recently entered) last: POV-Ray's per-ray interior
// list (pipeline §4 "Transmission/refraction"). Refraction takes its relative ior from it, interior fade applies
// when a ray leaves an interior it is in, and fresnel reflection reads it too.
//
// Identity: POV-Ray compares Interior pointers. Every placed object owns one interior, which CSG children without
// their own share with their parent. povtrace's render scene has no interior objects, so an interior is
// identified by the top-level object it belongs to plus its values: a union's children with the inherited
// interior are one interior (as in POV-Ray: the inner surfaces of a union of glass spheres refract), separate
// objects are separate interiors.
#pragma once

#include <array>
#include <cstdint>

#include "scene/description.hpp"

namespace povtrace::render {

struct MediaSet;   // renderer/media/render_media.hpp

struct InteriorRef {
  std::uint32_t object = 0;             // top-level scene object
  const Interior* interior = nullptr;   // its values (owned by the render scene's materials)
  const MediaSet* media = nullptr;      // its media ready for sampling, if it has any
};

inline bool same_interior(const InteriorRef& a, const InteriorRef& b) {
  if (a.object != b.object) return false;
  if (a.interior == b.interior) return true;
  const Interior& x = *a.interior;
  const Interior& y = *b.interior;
  return x.ior == y.ior && x.fade_distance == y.fade_distance && x.fade_power == y.fade_power &&
         x.fade_colour == y.fade_colour && x.refraction == y.refraction && x.hollow == y.hollow && x.media_id == y.media_id &&
         x.caustics == y.caustics;
}

class InteriorList {
 public:
  // Rays are copied at every bounce and most are in no interior at all: construction and copies touch only the
  // entries in use (the array is deliberately left uninitialised beyond count_).
  InteriorList() {}   // NOLINT: no zero-fill of entries_
  InteriorList(const InteriorList& o) : count_(o.count_) {
    for (int i = 0; i < count_; ++i) entries_[i] = o.entries_[i];
  }
  InteriorList& operator=(const InteriorList& o) {
    count_ = o.count_;
    for (int i = 0; i < count_; ++i) entries_[i] = o.entries_[i];
    return *this;
  }

  // Deeper nesting than this is not tracked (the entering is ignored), which only matters for scenes with more
  // than 32 nested or overlapping objects along one ray.
  static constexpr int capacity = 32;

  bool empty() const { return count_ == 0; }
  int size() const { return count_; }
  const InteriorRef& back() const { return entries_[count_ - 1]; }
  bool contains(const InteriorRef& r) const { return find(r) >= 0; }
  // True when every interior the ray is in is hollow (or it is in none): POV-Ray's "hollow ray", which fog reaches.
  bool any_media() const {
    for (int i = 0; i < count_; ++i)
      if (entries_[i].media) return true;
    return false;
  }
  const InteriorRef& operator[](int i) const { return entries_[i]; }
  bool all_hollow() const {
    for (int i = 0; i < count_; ++i)
      if (!entries_[i].interior->hollow) return false;
    return true;
  }
  void append(const InteriorRef& r) {
    if (count_ < capacity) entries_[count_++] = r;
  }
  // Removes the most recently entered occurrence of r; false if the ray was not in it.
  bool remove(const InteriorRef& r) {
    const int i = find(r);
    if (i < 0) return false;
    for (int k = i; k + 1 < count_; ++k) entries_[k] = entries_[k + 1];
    --count_;
    return true;
  }

 private:
  int find(const InteriorRef& r) const {
    for (int i = count_ - 1; i >= 0; --i)
      if (same_interior(entries_[i], r)) return i;
    return -1;
  }
  std::array<InteriorRef, capacity> entries_;
  int count_ = 0;
};

}  // namespace povtrace::render

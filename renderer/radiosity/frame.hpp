// Mapping pool directions (directions.hpp, cosine-weighted around +y) onto a surface, and the rule that picks
// which pool entries one new sample shoots (docs/issue19-study.md §4.2, §4.3; POV-Ray 3.7 source/backend/
// lighting/radiosity.cpp, SampleDirectionGenerator::InitSequence / GetDirection and their use in GatherLight).
#pragma once

#include <cstddef>

#include "renderer/radiosity/directions.hpp"
#include "scene/vecmath.hpp"

namespace povtrace::render::radiosity {

// How a pool direction (x, y, z) is placed around a frame normal n.
struct Frame {
  enum class Kind {
    as_is,     // n.y > 1 − 0.001: the pool direction is used unchanged (POV-Ray's shortcut within ~2.56° of +y)
    negated,   // n.y < −1 + 0.001: the pool direction negated
    rotated,   // otherwise: x·axis_x + y·n + z·axis_z
  };
  Kind kind = Kind::as_is;
  Vec3 axis_x{1, 0, 0};
  Vec3 normal{0, 1, 0};
  Vec3 axis_z{0, 0, 1};
};

// The frame around the unit normal n. axis_x = normalise(n × h), axis_z = normalise(axis_x × n), with the helper
// h = +y when |n.z| > 0.9, else +z (POV-Ray builds these axes in every case; only `rotated` uses them).
Frame make_frame(Vec3 n);

// The world direction of pool direction d in frame f.
Vec3 to_world(const Frame& f, Vec3 d);

// POV-Ray's `similar`: the sum of the absolute component differences is below 1e−10 (EPSILON).
bool similar_normals(Vec3 a, Vec3 b);

// The directions of one new sample (study §4.2). The sample shoots n = min(requested, M) rays. With no
// perturbed normal (`layer` similar to `raw`, which is always so unless radiosity's `normal on`), pool entries
// are mapped around `raw` and all used. With a perturbed normal they are mapped around `layer` and an entry is
// rejected (skipped) when its direction is not strictly above the raw surface (d·raw ≤ 0); 5n entries (at most M)
// may be tried in total. When they run out, the frame is rebuilt around `raw` and the remaining rays use the
// following entries unchecked. Entries are taken from the pool in order starting at `cursor`, cyclically; the
// cursor (one per block and bounce depth, owned by the caller) is advanced past every entry taken, rejected or not.
class SampleDirections {
 public:
  SampleDirections(const DirectionPool& pool, std::size_t& cursor, std::size_t requested, Vec3 raw, Vec3 layer);

  std::size_t count() const { return count_; }     // n
  // The next ray's direction; call it exactly count() times.
  Vec3 next();
  std::size_t raw_rays() const { return raw_rays_; }            // rays shot around the raw normal so far
  std::size_t layer_rays() const { return taken_ - raw_rays_; }  // rays shot around the perturbed normal
  // The normal to file the sample under: the raw one when strictly more of its rays used the raw frame.
  bool file_under_raw() const { return raw_rays_ > layer_rays(); }

 private:
  Vec3 take();                 // the next pool entry in the current frame; advances the cursor
  void fall_back_to_raw();

  const DirectionPool& pool_;
  std::size_t& cursor_;
  std::size_t count_;
  Vec3 raw_;
  Frame frame_;
  bool raw_mode_;
  std::size_t tries_left_;     // entries the perturbed frame may still try (unused in raw mode)
  std::size_t taken_ = 0;      // rays handed out
  std::size_t raw_rays_ = 0;
};

}  // namespace povtrace::render::radiosity

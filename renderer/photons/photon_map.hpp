// POV-Ray 3.7's surface photon map (docs/issue20-photons.md §3): photons stored as POV-Ray stores them (float
// position, colour in its 4-byte RGBE with exponent bias 250, incoming direction as two angles in signed bytes),
// a balanced kd-tree over them (the median of the widest extent at each level, kept in place), the gather radius
// estimated from the map's density when the scene does not give one, and the adaptive k-nearest gather with the
// search flattened along the surface normal.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "renderer/geometry.hpp"
#include "scene/description.hpp"

namespace povtrace::render::photons {

struct Photon {
  float position[3];
  std::uint8_t rgbe[4];
  std::int8_t theta, phi;   // the direction back toward where the photon came from
  std::uint8_t axis;        // kd-tree split axis of this node
};

// Encoding and decoding as POV-Ray does (colutils.cpp photon RGBE, photons.cpp addSurfacePhoton): lossy on purpose,
// so that gathered light matches POV-Ray's rounding.
Photon make_photon(Vec3 position, Vec3 colour, Vec3 to_origin);
Vec3 photon_colour(const Photon& p);
Vec3 photon_direction(const Photon& p);

// The C library's rand() as glibc computes it from its initial seed 1 (the additive feedback generator
// r[i] = r[i-3] + r[i-31] over a table filled from the seed by 16807·x mod 2^31−1, 310 outputs discarded). POV-Ray
// draws the photons that estimate the gather radius with rand() % count and never seeds it, so this gives its
// sample in the same order.
class CRandom {
 public:
  CRandom();
  int operator()() { return static_cast<int>(next_raw() >> 1); }

 private:
  std::uint32_t next_raw();
  std::uint32_t state_[31];
  int head_ = 0;
};

// The photons found around a point, nearest-first not guaranteed; `radius` is the radius the estimate divides by.
struct Gathered {
  std::vector<std::pair<double, const Photon*>> found;   // (stretched squared distance, photon), a max-heap
  double radius = 0;
};

class PhotonMap {
 public:
  // Builds the tree over `photons` and the gather options from `settings` (radius estimated when not given).
  // `tree_built`: the photons already are a tree in its array order (a loaded photon map file).
  PhotonMap(std::vector<Photon> photons, const PhotonSettings& settings, bool tree_built = false);
  const std::vector<Photon>& photons() const { return photons_; }

  std::size_t size() const { return photons_.size(); }
  double gather_radius() const { return min_radius_; }
  // POV-Ray's gatherPhotonsAdaptive: the gather_max nearest within the radius, once more with a larger radius when
  // fewer than gather_min were found, kept if the density did not change much (expand_thresholds).
  void gather_adaptive(Vec3 point, Vec3 normal, Gathered& out, std::vector<double>& scratch) const;
  // Up to `count` photons nearest to `point` within `radius` (flattened along `normal` if given); returns the
  // radius reached (`radius` when fewer were found).
  double gather(Vec3 point, double radius, int count, const Vec3* normal, Gathered& out,
                std::vector<double>& distances) const;

 private:
  void build(std::size_t begin, std::size_t end);
  void select_median(long left, long right, int axis, long mid);
  void estimate_radius(const PhotonSettings& settings);

  std::vector<Photon> photons_;
  int gather_min_ = 20, gather_max_ = 100;
  double expand_tolerance_ = 0.2;
  int expand_min_ = 35;
  double min_radius_ = 0;
  double radius_step_ = 0;
  int steps_ = 2;
};

}  // namespace povtrace::render::photons

// Integration of media along one ray segment, as POV-Ray 3.7 does it (interior/media.cpp ComputeMedia): the
// segment is split where lights' beams start and end (lit intervals), then into sampling intervals (`intervals`,
// shared out by `ratio`), sampled by method 1 (random points, extra samples until the variance passes the
// confidence test), 2 (evenly spaced, jittered) or 3 (adaptive: a row of points refined by aa_threshold down to
// aa_level, attenuated in order). Every POV-Ray quirk that shows in images is kept: method 3 spaces its points by
// 1/(n+1) of the interval, the three-point weights of its refinement, the phase functions averaged over all media.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/media/render_media.hpp"

namespace povtrace::render {

// What the integrator asks of the tracer: the light from light `index` reaching `point` after the shadow test
// (POV-Ray's TestShadow), and the direction to it; none when nothing arrives.
class MediaLighting {
 public:
  struct Arrival {
    Rgb colour;
    Vec3 to_light;
  };
  virtual std::optional<Arrival> arrival(std::size_t index, Vec3 point) = 0;

 protected:
  ~MediaLighting() = default;
};

// The random numbers of method 1 and of jitter. POV-Ray draws them from one sequence per thread, so its images
// with them vary run to run; povtrace seeds a sequence from the segment itself, so they do not.
class MediaRandom {
 public:
  explicit MediaRandom(std::uint64_t seed) : state_(seed) {}
  double next();   // uniform in [0, 1)

 private:
  std::uint64_t state_;
};
std::uint64_t media_seed(Vec3 origin, Vec3 direction, double depth);

// The media list of a segment (several interiors' media together, or the atmosphere's), at most this many.
struct MediaList {
  static constexpr int capacity = 64;
  const RenderMedia* items[capacity];
  int count = 0;
  void add(const MediaSet& set) {
    for (const RenderMedia& m : set.media)
      if (count < capacity) items[count++] = &m;
  }
};

struct MediaSegment {
  Vec3 origin, direction;   // direction of unit length
  double depth = 0;         // where the segment ends
  bool shadow_ray = false;  // only extinction counts (POV-Ray's IsShadowTestRay)
};

// What the media do to the colour arriving at the segment's far end: colour·transmittance + emitted; a transmit
// (alpha) channel is scaled by grey(transmittance).
struct MediaEffect {
  Rgb transmittance{1, 1, 1};
  Rgb emitted{0, 0, 0};
  Rgb apply(Rgb c) const { return {c.x * transmittance.x + emitted.x, c.y * transmittance.y + emitted.y,
                                   c.z * transmittance.z + emitted.z}; }
};

// `lights`: the scene's lights (those without media_interaction and shadowless ones light no media).
MediaEffect integrate_media(const MediaList& media, const MediaSegment& segment,
                            const std::vector<RenderLight>& lights, MediaLighting& lighting, MediaRandom& random);

// The lit intervals of a segment from the lights' beams (exposed for tests): [s0, s1] pieces covering
// [0, depth], in order, `lit` where at least one light's beam is.
struct LitInterval {
  bool lit = false;
  double s0 = 0, s1 = 0;
};
std::vector<LitInterval> lit_intervals(const MediaSegment& segment, const std::vector<RenderLight>& lights);

}  // namespace povtrace::render

#include "renderer/radiosity/frame.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace povtrace::render::radiosity {

namespace {
constexpr double pole_limit = 1 - 0.001;        // RAD_EPSILON: within ~2.56° of ±y the pool is used as is
constexpr double helper_switch = 0.9;           // |n.z| above this: the helper axis is +y instead of +z
constexpr double similar_epsilon = 1e-10;       // EPSILON of POV-Ray's `similar`
constexpr std::size_t perturbed_try_factor = 5; // a perturbed frame may try 5n pool entries
}  // namespace

Frame make_frame(Vec3 n) {
  Frame f;
  f.normal = n;
  const Vec3 helper = std::fabs(n.z) > helper_switch ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
  f.axis_x = normalize(cross(n, helper));
  f.axis_z = normalize(cross(f.axis_x, n));
  f.kind = n.y > pole_limit ? Frame::Kind::as_is : n.y < -pole_limit ? Frame::Kind::negated : Frame::Kind::rotated;
  return f;
}

Vec3 to_world(const Frame& f, Vec3 d) {
  switch (f.kind) {
    case Frame::Kind::as_is: return d;
    case Frame::Kind::negated: return -d;
    case Frame::Kind::rotated: break;
  }
  return f.axis_x * d.x + f.normal * d.y + f.axis_z * d.z;
}

bool similar_normals(Vec3 a, Vec3 b) {
  return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z) < similar_epsilon;
}

SampleDirections::SampleDirections(const DirectionPool& pool, std::size_t& cursor, std::size_t requested, Vec3 raw,
                                   Vec3 layer)
    : pool_(pool), cursor_(cursor), count_(std::min(requested, pool.size())), raw_(raw),
      raw_mode_(similar_normals(raw, layer)),
      tries_left_(std::min(count_ * perturbed_try_factor, pool.size())) {
  frame_ = make_frame(raw_mode_ ? raw : layer);
}

Vec3 SampleDirections::take() {
  const Vec3 d = to_world(frame_, pool_.cyclic(cursor_));
  cursor_ = (cursor_ + 1) % pool_.size();
  return d;
}

void SampleDirections::fall_back_to_raw() {
  raw_mode_ = true;
  frame_ = make_frame(raw_);
}

Vec3 SampleDirections::next() {
  assert(taken_ < count_);
  ++taken_;
  // Perturbed frame: skip entries below the raw surface while the budget of tries lasts. POV-Ray checks the
  // budget before each try, so an exhausted budget falls back even if the last try was accepted.
  while (!raw_mode_ && tries_left_ > 0) {
    --tries_left_;
    const Vec3 d = take();
    if (dot(d, raw_) > 0) return d;
  }
  if (!raw_mode_) fall_back_to_raw();
  ++raw_rays_;
  return take();
}

}  // namespace povtrace::render::radiosity

// The photon map's storage, tree and gather (photon_map.hpp). The behaviour reproduced is POV-Ray 3.7's
// (lighting/photons.cpp PhotonMap, PhotonGatherer; colour/colutils.cpp), written anew: see docs/issue20-photons.md.
#include "renderer/photons/photon_map.hpp"

#include <algorithm>
#include <cmath>

namespace povtrace::render::photons {

namespace {
constexpr int kExponentBias = 250;   // POV-Ray's photon RGBE bias: photon energies are mostly far below 1

std::int8_t angle_byte(double angle) { return static_cast<std::int8_t>(angle * 127.0 / M_PI); }
double byte_angle(std::int8_t b) { return static_cast<double>(b) * M_PI / 127.0; }
std::uint8_t channel_byte(float c, float scale) {
  const float v = c * scale;
  return v <= 0.0f ? 0 : static_cast<std::uint8_t>(std::min(v, 255.0f));
}

Vec3 position_of(const Photon& p) { return {p.position[0], p.position[1], p.position[2]}; }
double component(const Photon& p, int axis) { return p.position[axis]; }
double component(Vec3 v, int axis) { return axis == 0 ? v.x : axis == 1 ? v.y : v.z; }
}  // namespace

Photon make_photon(Vec3 position, Vec3 colour, Vec3 to_origin) {
  Photon p{};
  p.position[0] = static_cast<float>(position.x);
  p.position[1] = static_cast<float>(position.y);
  p.position[2] = static_cast<float>(position.z);
  const float r = static_cast<float>(colour.x), g = static_cast<float>(colour.y), b = static_cast<float>(colour.z);
  const float v = std::max({r, g, b});
  if (v >= 1e-32f) {
    int e = 0;
    const float scale = static_cast<float>(std::frexp(v, &e) * 256.0 / v);
    p.rgbe[0] = channel_byte(r, scale);
    p.rgbe[1] = channel_byte(g, scale);
    p.rgbe[2] = channel_byte(b, scale);
    p.rgbe[3] = static_cast<std::uint8_t>((e + kExponentBias) & 0xff);   // wraps above 2^5, as POV-Ray's byte does
  }
  const Vec3 d = normalize(to_origin);
  const double horizontal = std::sqrt(d.x * d.x + d.z * d.z);
  double phi = horizontal > 0 ? std::acos(std::clamp(d.x / horizontal, -1.0, 1.0)) : 0.0;
  if (d.z < 0) phi = -phi;
  double theta = std::acos(std::min(horizontal, 1.0));
  if (d.y < 0) theta = -theta;
  p.theta = angle_byte(theta);
  p.phi = angle_byte(phi);
  return p;
}

namespace {
// Decoding tables, computed once (every gathered photon is decoded): the scale of each exponent byte, and the sine
// and cosine of each angle byte.
struct DecodeTables {
  float scale[256];
  double sine[256], cosine[256];
  DecodeTables() {
    scale[0] = 0;
    for (int e = 1; e < 256; ++e) scale[e] = static_cast<float>(std::ldexp(1.0, e - (kExponentBias + 8)));
    for (int b = -128; b < 128; ++b) {
      sine[b + 128] = std::sin(byte_angle(static_cast<std::int8_t>(b)));
      cosine[b + 128] = std::cos(byte_angle(static_cast<std::int8_t>(b)));
    }
  }
};
const DecodeTables& tables() {
  static const DecodeTables t;
  return t;
}
}  // namespace

Vec3 photon_colour(const Photon& p) {
  const float f = tables().scale[p.rgbe[3]];
  return {p.rgbe[0] * f, p.rgbe[1] * f, p.rgbe[2] * f};
}

Vec3 photon_direction(const Photon& p) {
  const DecodeTables& t = tables();
  const double c = t.cosine[p.theta + 128];
  return {c * t.cosine[p.phi + 128], t.sine[p.theta + 128], c * t.sine[p.phi + 128]};
}

PhotonMap::PhotonMap(std::vector<Photon> photons, const PhotonSettings& settings, bool tree_built)
    : photons_(std::move(photons)), gather_min_(settings.gather_min), gather_max_(settings.gather_max),
      expand_tolerance_(settings.expand_tolerance), expand_min_(settings.expand_min) {
  if (!tree_built) build(0, photons_.size());
  if (photons_.empty()) return;
  min_radius_ = settings.radius;
  if (!(min_radius_ > 0)) estimate_radius(settings);
  min_radius_ *= settings.radius_multiplier;
  radius_step_ = 2.0 * min_radius_;
}


CRandom::CRandom() {
  std::int32_t r[31];
  r[0] = 1;
  for (int i = 1; i < 31; ++i) {
    const std::int32_t hi = r[i - 1] / 127773, lo = r[i - 1] % 127773;
    std::int32_t word = 16807 * lo - 2836 * hi;
    if (word < 0) word += 2147483647;
    r[i] = word;
  }
  for (int i = 0; i < 31; ++i) state_[i] = static_cast<std::uint32_t>(r[i]);
  head_ = 3;   // r[31..33] repeat r[0..2]: the ring already holds them
  for (int i = 0; i < 310; ++i) (void)next_raw();
}

std::uint32_t CRandom::next_raw() {
  // state_ holds the last 31 values, the oldest at head_; the new one is the oldest plus the one three back.
  const std::uint32_t v = state_[head_] + state_[(head_ + 28) % 31];
  state_[head_] = v;
  head_ = (head_ + 1) % 31;
  return v;
}

// A balanced tree kept in the array, built as POV-Ray builds it (sortAndSubdivide): each range's median along the
// axis of its widest extent is put in its middle by a median-of-three quickselect, smaller ones before it. A range
// of two is left as it is (POV-Ray selects only in ranges of three or more), so its second photon may lie on the
// wrong side of the first; the search misses it then, as POV-Ray's does.
void PhotonMap::build(std::size_t begin, std::size_t end) {
  if (begin >= end) return;
  const std::size_t last = end - 1;
  if (begin == last) {
    photons_[begin].axis = 0;
    return;
  }
  float lo[3] = {HUGE_VALF, HUGE_VALF, HUGE_VALF}, hi[3] = {-HUGE_VALF, -HUGE_VALF, -HUGE_VALF};
  for (std::size_t i = begin; i < end; ++i)
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], photons_[i].position[a]);
      hi[a] = std::max(hi[a], photons_[i].position[a]);
    }
  int axis = 0;
  if (hi[1] - lo[1] > hi[axis] - lo[axis]) axis = 1;
  if (hi[2] - lo[2] > hi[axis] - lo[axis]) axis = 2;
  const std::size_t mid = (begin + last) / 2;
  if (last - begin >= 2) select_median(static_cast<long>(begin), static_cast<long>(last), axis, static_cast<long>(mid));
  photons_[mid].axis = static_cast<std::uint8_t>(axis);
  build(begin, mid);
  build(mid + 1, end);
}

// Quickselect over [left, right] (inclusive) until `mid` holds its order statistic along `axis`: the middle element
// and the ends are ordered so that the median of the three becomes the pivot at `left`, the rest is partitioned
// around it by two scans toward each other, the pivot goes between, and only the side holding `mid` goes on.
void PhotonMap::select_median(long left, long right, int axis, long mid) {
  const auto v = [&](long i) { return photons_[static_cast<std::size_t>(i)].position[axis]; };
  const auto swap = [&](long a, long b) { std::swap(photons_[static_cast<std::size_t>(a)], photons_[static_cast<std::size_t>(b)]); };
  while (left < right) {
    swap((left + right) / 2, left + 1);
    if (v(left + 1) > v(right)) swap(left + 1, right);
    if (v(left) > v(right)) swap(left, right);
    if (v(left + 1) > v(left)) swap(left + 1, left);
    long j = left + 1, k = right;
    while (j <= k) {
      for (++j; j <= right && v(j) < v(left); ++j) {}
      for (--k; k >= left && v(k) > v(left); --k) {}
      if (j < k) swap(j, k);
    }
    swap(left, k);
    if (k - left > 0 && mid >= left && mid < k) right = k - 1;
    else if (right - k > 0 && mid > k && mid <= right) left = k + 1;
    else break;
  }
}

namespace {
// The k-nearest search (POV-Ray's gatherPhotonsRec with its heap): distances squared, optionally stretched along
// the normal so that the search region is a disc on the surface rather than a ball.
struct Search {
  const std::vector<Photon>& photons;
  Vec3 point;
  const Vec3* normal;
  std::size_t count;
  std::vector<std::pair<double, const Photon*>>& heap;   // max-heap by distance
  double limit;        // squared radius so far
  double root_limit;   // its square root

  void run(std::size_t begin, std::size_t end) {
    if (begin >= end) return;
    const std::size_t mid = (begin + end - 1) / 2;
    const Photon& p = photons[mid];
    const int axis = p.axis;
    const Vec3 v = position_of(p) - point;
    const double along = component(v, axis);
    if (!(along * along > limit)) consider(p, v);
    const double split = component(p, axis), here = component(point, axis);
    if (here - split < 0) {
      if (here - root_limit < split) run(begin, mid);
      if (here + root_limit > split) run(mid + 1, end);
    } else {
      if (here + root_limit > split) run(mid + 1, end);
      if (here - root_limit < split) run(begin, mid);
    }
  }
  void consider(const Photon& p, Vec3 v) {
    double d = dot(v, v);
    if (normal) d += std::fabs(dot(*normal, v)) * d * 16.0;
    if (!(d < limit)) return;
    if (heap.size() < count) {
      heap.emplace_back(d, &p);
      std::push_heap(heap.begin(), heap.end());
      return;
    }
    // Full: the farthest gives way, and the search narrows to the new farthest.
    std::pop_heap(heap.begin(), heap.end());
    heap.back() = {d, &p};
    std::push_heap(heap.begin(), heap.end());
    limit = heap.front().first;
    root_limit = std::sqrt(limit);
  }
};
}  // namespace

double PhotonMap::gather(Vec3 point, double radius, int count, const Vec3* normal, Gathered& out,
                         std::vector<double>& /*unused*/) const {
  out.found.clear();
  if (photons_.empty() || count <= 0) {
    out.radius = radius;
    return radius;
  }
  Search s{photons_, point, normal, static_cast<std::size_t>(count), out.found, radius * radius, radius};
  s.run(0, photons_.size());
  out.radius = s.root_limit;
  return out.radius;
}

void PhotonMap::gather_adaptive(Vec3 point, Vec3 normal, Gathered& out, std::vector<double>& scratch) const {
  double size = min_radius_;
  double radius = gather(point, size, gather_max_, &normal, out, scratch);
  auto density = [](std::size_t n, double r) { return static_cast<double>(n) / (r * r); };
  double previous = density(out.found.size(), radius);
  if (previous == 0) previous = 1e-16;
  Gathered wider;
  for (int step = 1; static_cast<int>(out.found.size()) < gather_min_ && step < steps_;) {
    ++step;
    size += radius_step_;
    const double r = gather(point, size, gather_max_, &normal, wider, scratch);
    const std::size_t n = wider.found.size();
    const double now = density(n, r);
    if ((now - previous) / previous < expand_tolerance_ || (static_cast<int>(n) < expand_min_ && n > 0)) {
      previous = now == 0 ? 1e-16 : now;
      std::swap(out, wider);
    } else {
      break;
    }
  }
}

// POV-Ray's setGatherOptions for a surface map: the average density at a sample of photons (each measured by its
// gather_max nearest), the radius that holds gather_max photons at that density, widened where a second sample finds
// sparse regions. The samples are POV-Ray's: rand() % count into the built tree.
void PhotonMap::estimate_radius(const PhotonSettings& settings) {
  const std::size_t n = photons_.size();
  const std::size_t samples = std::clamp<std::size_t>(n / 20, 100, 1000);
  CRandom random;
  const auto pick = [&] { return position_of(photons_[static_cast<std::size_t>(random()) % n]); };
  Gathered g;
  std::vector<double> scratch;
  double sum = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double r = gather(pick(), 1e7, settings.gather_max, nullptr, g, scratch);
    const double d = r > 0 ? static_cast<double>(g.found.size()) / (M_PI * r * r) : (i > 0 ? sum / static_cast<double>(i) : 0.0);
    sum += d;
  }
  const double average = sum / static_cast<double>(samples);
  min_radius_ = average > 0 ? std::sqrt(settings.gather_max / (average * M_PI)) : 1e7;
  std::size_t sparse = 0;
  for (std::size_t i = 0; i < samples; ++i) {
    const double r = gather(pick(), min_radius_, settings.gather_max, nullptr, g, scratch);
    if (!(r > 0)) continue;
    const double d = static_cast<double>(g.found.size()) / (M_PI * r * r);
    if (d < average * 0.7 && d > average * 0.05) ++sparse;
  }
  min_radius_ *= 1.0 + 20.0 * static_cast<double>(sparse) / static_cast<double>(samples);
}

}  // namespace povtrace::render::photons

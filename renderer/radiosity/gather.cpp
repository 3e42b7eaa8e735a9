#include "renderer/radiosity/gather.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "renderer/radiosity/frame.hpp"
#include "renderer/radiosity/octree.hpp"

namespace povtrace::render::radiosity {

namespace {
constexpr double kEpsilon = 1e-10;        // POV-Ray's EPSILON: the sample-ray weight stays above the bailout
constexpr double kNearHitFactor = 1e-4;   // a sample whose shortest ray is below this × its maximum radius is not kept
constexpr double kBoundHuge = 2e10;       // POV-Ray's BOUND_HUGE: the shortest ray before any hit

double grey(Vec3 c) { return 0.297 * c.x + 0.589 * c.y + 0.114 * c.z; }

// max_sample (study §4.5): a ray colour brighter than the limit in its largest channel is scaled down to it.
Vec3 clamp_to_max_sample(Vec3 c, double max_sample) {
  const double m = std::max({c.x, c.y, c.z});
  if (m > max_sample && max_sample > 0) return c * (max_sample / m);
  return c;
}

// The quality factor of a kept ray whose first object has importance p < 1 (study §4.4): n/(⌊p·(n−1)⌋ + 1), in
// single precision as POV-Ray computes it; it compensates for the rays dropped at that object.
double importance_compensation(float p, int n) {
  if (!(p < 1.0f)) return 1.0;
  const auto last = static_cast<unsigned>(std::floor(p * static_cast<float>(n - 1)));
  return static_cast<float>(n) / static_cast<float>(last + 1);
}
}  // namespace

Gatherer::Gatherer(const RenderRadiosity& radiosity, Vec3 camera)
    : radiosity_(radiosity), camera_(camera), error_bound_(radiosity.settings.error_bound),
      cursors_(radiosity.depths.size(), 0) {}

void Gatherer::set_pass(int pass) {
  pass_ = pass;
  final_pass_ = pass == final_pass_id;
  error_bound_ = final_pass_ ? radiosity_.settings.error_bound
                             : radiosity_.settings.error_bound * radiosity_.settings.low_error_factor;
}

void Gatherer::begin_block(int tile, int pass) {
  tile_ = tile;
  set_pass(pass);
  std::fill(cursors_.begin(), cursors_.end(), 0);
  block_.clear();
  top_queries_ = 0;
  top_reuse_ = 0;
}

Gatherer::Lookup Gatherer::lookup(const Query& q) {
  Lookup out;
  Vec3 sum;
  auto visit = [&](const CachedSample& s) {
    const double w = sample_weight(q, s.geometry);
    if (w <= 0) return;
    out.weight_sum += w;
    sum += s.illuminance * w;
  };
  if (global_) for_each_candidate(*global_, block_, q.point, scratch_, visit, q.depth);
  else {
    scratch_.clear();
    block_.covering(q.point, scratch_, q.depth);
    for (const std::uint32_t id : scratch_) visit(block_[id]);
  }
  if (out.weight_sum > 0) out.illuminance = sum / out.weight_sum;
  return out;
}

// ComputeAmbient (study §3.3, §3.4).
Vec3 Gatherer::ambient(const AmbientQuery& q, SampleTracer& tracer) {
  assert(q.depth >= 0 && static_cast<std::size_t>(q.depth) < radiosity_.depths.size());
  const RadiositySettings& s = radiosity_.settings;
  const DepthSettings& ds = radiosity_.depths[static_cast<std::size_t>(q.depth)];
  const Vec3 normal = s.normal ? q.layer_normal : q.raw_normal;
  double e = error_bound_;
  if (q.weight < weak_ray_weight) e += weak_ray_weight - q.weight;
  const Query query{q.point, normal, e * ds.error_bound_factor, q.depth, final_pass_};
  Lookup found = lookup(query);
  double reuse = found.weight_sum;
  if (q.depth == 0) {
    ++top_queries_;
    top_reuse_ = static_cast<float>(top_reuse_ + reuse * 4);
  }
  Vec3 a = found.illuminance;
  if (!reuse_is_enough(reuse, ds.reuse_count, final_pass_, s.always_sample)) {
    const Gathered g = gather(q, normal, tracer);
    a = reuse > 0 ? (a * reuse + g.illuminance * g.quality) / (reuse + g.quality) : g.illuminance;
    reuse += g.quality;
  }
  quality_ = quality_after_query(quality_, reuse, ds.reuse_count);
  a = a * (1.0 - s.gray_threshold) + Vec3{1, 1, 1} * (s.gray_threshold * grey(a));
  return a * s.brightness;
}

// GatherLight (study §4).
Gatherer::Gathered Gatherer::gather(const AmbientQuery& q, Vec3 effective_normal, SampleTracer& tracer) {
  const RadiositySettings& s = radiosity_.settings;
  const auto depth = static_cast<std::size_t>(q.depth);
  const DepthSettings& ds = radiosity_.depths[depth];
  const double to_eye = length(camera_ - q.point);
  const double reuse_min = to_eye * ds.minimum_reuse;
  const double reuse_max = ds.maximum_reuse >= HUGE_VAL ? HUGE_VAL : to_eye * ds.maximum_reuse;

  SampleRayParams params;
  params.depth = q.depth + 1;
  params.level = ds.trace_level + 1;
  params.max_level = std::max(q.max_level, ds.trace_level + 1);
  params.adc_bailout = s.adc_bailout;
  params.weight = std::max(s.adc_bailout + kEpsilon, ds.weight);

  SampleDirections directions(radiosity_.pool, cursors_[depth], static_cast<std::size_t>(ds.rays), q.raw_normal,
                              effective_normal);
  const int n = static_cast<int>(directions.count());
  const float saved_quality = quality_;
  Vec3 colour_sum;
  double quality_sum = 0, inverse_distance_sum = 0, smallest = kBoundHuge;
  Vec3 to_nearest;
  for (int i = 0; i < n; ++i) {
    const Vec3 d = directions.next();
    quality_ = 1.0f;   // POV-Ray resets the ticket's quality for every ray; deeper queries lower it
    params.importance_queried = static_cast<float>(i) / static_cast<float>(n - 1);
    const unsigned long writes = importance_writes_;
    const SampleRayResult r = tracer.trace_sample(q.point, d, params);
    // The ticket's importance after the ray: its own, or the last one a sample ray below it found (importance_found).
    const float found = importance_writes_ != writes ? found_importance_ : r.importance;
    if (r.kept && !(found < params.importance_queried)) {
      const double quality = static_cast<double>(quality_) * importance_compensation(found, n);
      quality_sum += quality;
      colour_sum += clamp_to_max_sample(r.colour, s.max_sample) * quality;
    }
    const double t = std::min(r.depth, HUGE_VAL);   // every ray's distance counts, kept or not
    if (t < smallest) {
      smallest = t;
      to_nearest = d;
    }
    inverse_distance_sum += 1.0 / t;
  }
  const Vec3 illuminance = quality_sum == 0 ? colour_sum : colour_sum / quality_sum;
  const double quality = quality_sum / n;
  double mean = n / inverse_distance_sum;   // harmonic mean; ∞ when every ray missed
  if (smallest > reuse_max * kNearHitFactor) {
    if (mean < reuse_min) mean = reuse_min;   // in this order, as POV-Ray clamps
    if (mean > reuse_max) mean = reuse_max;
    SampleGeometry g;
    g.point = q.point;
    g.normal = directions.file_under_raw() ? q.raw_normal : effective_normal;
    g.to_nearest = to_nearest;
    g.radius = static_cast<float>(mean);
    g.nearest = static_cast<float>(smallest);
    g.quality = static_cast<float>(quality);
    g.depth = q.depth;
    g.pass = pass_;
    g.tile = tile_;
    block_.add(filing_node(q.point, mean * filing_factor(s.error_bound, q.depth)), CachedSample{g, illuminance},
               q.depth);
  }
  quality_ = std::max(saved_quality, static_cast<float>(quality));
  return {illuminance, quality};
}

}  // namespace povtrace::render::radiosity

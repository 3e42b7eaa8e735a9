// Rainbows (POV-Ray 3.7's Trace::ComputeRainbow, source/backend/render/trace.cpp, 3.7-stable, read for the facts):
// applied to every non-shadow ray outside non-hollow objects, after its surface or sky colour and before media and
// fog. For each rainbow, with D the unit ray direction:
// - the angle between D's projection on the (right, up) plane and up, |acos(y / √(x² + y²))| (acos(y) when the
//   projection is zero), must be within the arc angle; D · direction must be ≥ 0;
// - index = (acos(D · direction) − angle) / width, moved by jitter · (2u − 1) for a uniform u; it must be in
//   [0, 1 − 1e-10]; the colour map at index gives C (filter f, transmit t);
// - fade = 0, or beyond the falloff angle s²(3 − 2s) with s = (angle − falloff) / falloff width;
// - k = max(e^(−depth / distance), fade·(1 − t) + t), f′ = f·(1 − k); the rainbow adds
//   k·colour·((1 − f′) + f′·C) + (1 − k)·C to a sum, and multiplies the ray's filter and transmit by k·f and k·t;
// - the ray's colour becomes the sum divided by the number of rainbows that added to it.
// A miss is BOUND_HUGE away. Jitter: POV-Ray draws u from its thread's random generator, in the order its threads
// trace rays; povtrace draws it from a hash of the ray, the same for any thread count: statistically the same
// jitter, not the same pixels.
#include <algorithm>
#include <cmath>
#include <cstdint>

#include "renderer/shading_helpers.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON

// A uniform number in [0, 1) that depends only on the ray.
double ray_random(const Ray& ray) {
  const std::uint64_t h = hash_of_values(0x9E3779B97F4A7C15ull, {ray.origin.x, ray.origin.y, ray.origin.z,
                                                                 ray.direction.x, ray.direction.y, ray.direction.z});
  return static_cast<double>(h >> 11) * 0x1.0p-53;
}
}  // namespace

Radiance Tracer::with_rainbows(const Ray& ray, double depth, Radiance r) const {
  Rgb sum{0, 0, 0};
  double transmit = 1.0;   // POV-Ray also multiplies the ray's filter; povtrace's rays carry only the transmit
  int n = 0;
  for (const RenderScene::RenderRainbow& entry : scene_.rainbows) {
    const Rainbow& rb = entry.rainbow;
    const double x = dot(ray.direction, rb.right);
    double y = dot(ray.direction, rb.up);
    double l = x * x + y * y;
    if (l > 0.0) {
      l = std::sqrt(l);
      y /= l;
    }
    const double angle = std::fabs(std::acos(y));
    if (!(angle <= rb.arc_angle)) continue;
    const double along = dot(ray.direction, rb.antisolar);
    if (!(along >= 0.0)) continue;
    double index = (std::acos(along) - rb.angle) / rb.width;
    if (rb.jitter > 0.0) index += (2.0 * ray_random(ray) - 1.0) * rb.jitter;
    if (!(index >= 0.0 && index <= 1.0 - kEpsilon)) continue;
    const Colour c = evaluate_pigment(entry.colour_map, Vec3{index, 0, 0});
    double fade = 0.0;
    if (rb.falloff_width > 0.0 && angle > rb.falloff_angle) {
      fade = (angle - rb.falloff_angle) / rb.falloff_width;
      fade = (3.0 - 2.0 * fade) * fade * fade;
    }
    double k = std::exp(-depth / rb.distance);
    k = std::max(k, fade * (1.0 - c.t) + c.t);   // the map's transmit is the least that shows through
    const double ki = 1.0 - k;
    const double f = c.f * ki;
    sum.x += k * r.colour.x * ((1.0 - f) + f * c.r) + ki * c.r;
    sum.y += k * r.colour.y * ((1.0 - f) + f * c.g) + ki * c.g;
    sum.z += k * r.colour.z * ((1.0 - f) + f * c.b) + ki * c.b;
    transmit *= k * c.t;
    ++n;
  }
  if (n == 0) return r;
  const double share = 1.0 / n;
  r.colour = sum * share;
  r.transmit *= transmit;
  return r;
}

}  // namespace povtrace::render

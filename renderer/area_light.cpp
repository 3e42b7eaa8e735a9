// Area light shadows (povray-pixel-pipeline.md §3 "area_light"), as POV-Ray 3.7's TraceAreaLightShadowRay and
// TraceAreaLightSubsetShadowRay compute them (facts read from source/backend/render/trace.cpp, 3.7-stable):
// - Sample (u, v) of an n1 × n2 grid sits at centre + (u/(n1−1) − ½)·axis1 + (v/(n2−1) − ½)·axis2 (no offset on
//   an axis with one sample). Its value is the light colour (spot and fade already applied at the centre) times
//   the shadow filter along the ray to the sample.
// - The grid is combined recursively: a region's value is the mean of its four corner samples; while the region
//   is wider than one cell it is split at floor/ceil of its midpoint into four sub-regions whose values replace
//   the corners — always below depth `adaptive`, and deeper only where two adjacent corners differ by more than
//   0.1 (sum of the channel differences). A sample is computed once per shading point.
// - `orient` turns the grid to face the shaded point: axis1 ⟂ the light direction and z (or y when the light
//   direction is within 0.01 of ±z), axis2 ⟂ both; both get axis1's length.
// - `circular` maps the square grid onto a disc (the +0.001 offset keeps the centre sample defined).
// - `jitter`: POV-Ray moves each sample randomly within ±½ cell, differently at every render. povtrace uses its
//   own deterministic offsets, hashed from the shaded point and the sample, so images do not change between runs
//   or thread counts.
// - A parallel area light shines along (sample − point_at) from every sample.
#include <cmath>
#include <cstdint>
#include <cstring>

#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {

double channel_distance(Rgb a, Rgb b) { return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z); }

std::uint64_t mix(std::uint64_t h) {   // splitmix64's finaliser
  h += 0x9E3779B97F4A7C15ull;
  h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
  h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
  return h ^ (h >> 31);
}

std::uint64_t bits_of(double d) {
  std::uint64_t b;
  std::memcpy(&b, &d, sizeof b);
  return b;
}

// How far a jittered sample moves along each axis, in sample spacings.
struct Jitter {
  double du, dv;
};

// Two numbers in [−½, ½) that depend only on the shaded point and the sample.
Jitter jitter_offsets(Vec3 point, int u, int v) {
  std::uint64_t h = mix(bits_of(point.x) ^ mix(bits_of(point.y) ^ mix(bits_of(point.z))));
  h = mix(h ^ (static_cast<std::uint64_t>(u) << 32 | static_cast<std::uint32_t>(v)));
  return {static_cast<double>(h >> 11) * 0x1.0p-53 - 0.5, static_cast<double>(mix(h) >> 11) * 0x1.0p-53 - 0.5};
}

}  // namespace

struct Tracer::AreaSampling {
  const RenderLight& light;
  Vec3 point;
  Rgb colour;              // light colour at the centre, before shadowing
  Vec3 axis1, axis2;
  const RayState& state;
  std::vector<Rgb>& grid;  // computed samples (x < 0: not yet), filled in as they are taken
};

Rgb Tracer::area_light_shadow(const RenderLight& l, Vec3 point, Vec3 to_light, Rgb colour, const RayState& state) {
  const Light& light = l.light;
  Vec3 axis1 = light.axis1, axis2 = light.axis2;
  if (light.orient) {
    const double length1 = length(axis1);
    const Vec3 helper = std::fabs(std::fabs(to_light.z) - 1.0) < 0.01 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
    axis1 = normalize(cross(to_light, helper));
    axis2 = normalize(cross(to_light, axis1)) * length1;
    axis1 = axis1 * length1;
  }
  // One result per sample, computed at most once for this point (the shadow test traces no further light, so the
  // buffer is never in use twice at once).
  area_grid_.assign(static_cast<std::size_t>(light.size1) * light.size2, Rgb{-1, 0, 0});
  AreaSampling s{l, point, colour, axis1, axis2, state, area_grid_};
  return area_subset(s, 0, 0, light.size1 - 1, light.size2 - 1, 0);
}

Rgb Tracer::area_sample(const AreaSampling& s, int u, int v) {
  const Light& light = s.light.light;
  Rgb& cached = s.grid[static_cast<std::size_t>(u) * light.size2 + v];
  if (cached.x >= 0) return cached;
  double ju = u, jv = v;
  if (light.jitter) {
    const Jitter j = jitter_offsets(s.point, u, v);
    ju += j.du;
    jv += j.dv;
  }
  Vec3 offset{0, 0, 0};
  if (light.circular && light.size1 > 1 && light.size2 > 1) {
    ju = ju / (light.size1 - 1) - 0.5 + 0.001;
    jv = jv / (light.size2 - 1) - 0.5 + 0.001;
    const double scale = std::max(std::fabs(ju), std::fabs(jv)) / std::sqrt(ju * ju + jv * jv);
    offset = s.axis1 * (ju * scale) + s.axis2 * (jv * scale);
  } else {
    if (light.size1 > 1) offset += s.axis1 * (ju / (light.size1 - 1) - 0.5);
    if (light.size2 > 1) offset += s.axis2 * (jv / (light.size2 - 1) - 0.5);
  }
  const Vec3 sample = light.location + offset;
  Vec3 direction = sample - s.point;
  double distance = length(direction);
  direction = direction / distance;
  if (light.parallel) {
    const Vec3 beam = normalize(sample - light.point_at);
    distance *= dot(beam, direction);
    direction = beam;
  }
  const Rgb f = shadow_filter(s.light, s.point, direction, distance, s.state);
  cached = Rgb{s.colour.x * f.x, s.colour.y * f.y, s.colour.z * f.z};
  return cached;
}

Rgb Tracer::area_subset(const AreaSampling& s, int u1, int v1, int u2, int v2, int level) {
  Rgb corner[4] = {area_sample(s, u1, v1), area_sample(s, u2, v1), area_sample(s, u1, v2), area_sample(s, u2, v2)};
  if (u2 - u1 > 1 || v2 - v1 > 1) {
    if (level < s.light.light.adaptive || channel_distance(corner[0], corner[1]) > 0.1 ||
        channel_distance(corner[1], corner[3]) > 0.1 || channel_distance(corner[3], corner[2]) > 0.1 ||
        channel_distance(corner[2], corner[0]) > 0.1) {
      const int mu_lo = static_cast<int>(std::floor((u1 + u2) / 2.0));
      const int mu_hi = static_cast<int>(std::ceil((u1 + u2) / 2.0));
      const int mv_lo = static_cast<int>(std::floor((v1 + v2) / 2.0));
      const int mv_hi = static_cast<int>(std::ceil((v1 + v2) / 2.0));
      corner[0] = area_subset(s, u1, v1, mu_lo, mv_lo, level + 1);
      corner[1] = area_subset(s, mu_hi, v1, u2, mv_lo, level + 1);
      corner[2] = area_subset(s, u1, mv_hi, mu_lo, v2, level + 1);
      corner[3] = area_subset(s, mu_hi, mv_hi, u2, v2, level + 1);
    }
  }
  return (corner[0] + corner[1] + corner[2] + corner[3]) * 0.25;
}

}  // namespace povtrace::render

// Pigment evaluation (povray-sdl-and-geometry.md §11; POV-Ray 3.7 pigment.cpp Compute_Pigment, warps.cpp
// Warp_EPoint, pattern.cpp Search_Blend_Map).
#include <algorithm>
#include <cmath>

#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {
// POV-Ray clamps warped coordinates to ±1e17 (warps.cpp COORDINATE_LIMIT).
constexpr double kCoordinateLimit = 1.0e17;

Vec3 displaced(Vec3 p, const Turbulence& t) {
  const Vec3 d = vector_turbulence(p, t);
  return {p.x + d.x * t.amount.x, p.y + d.y * t.amount.y, p.z + d.z * t.amount.z};
}

// POV-Ray's repeat warp (Warp_EPoint): the slab number is kept in single precision, as POV-Ray does.
Vec3 repeated(Vec3 p, const RepeatWarp& r) {
  const auto slab = static_cast<float>(std::floor(p[r.axis] / r.width));
  Vec3 q = p;
  q[r.axis] = p[r.axis] - slab * r.width;
  if ((static_cast<int>(slab) & 1) != 0) {
    q = {q.x * r.flip.x, q.y * r.flip.y, q.z * r.flip.z};
    if (r.flip[r.axis] < 0) q[r.axis] = r.width + q[r.axis];
  }
  return q + r.offset * static_cast<double>(slab);
}
}  // namespace

Vec3 to_pattern_space(const RenderPigment& pigment, Vec3 p) {
  for (const PatternStep& s : pigment.steps) {
    if (s.transformed) p = s.pattern_from_world.point(p);
    if (s.turbulence) p = displaced(p, *s.turbulence);
    if (s.repeat) p = repeated(p, *s.repeat);
  }
  if (pigment.classic_turbulence_warps) p = displaced(p, *pigment.params.turbulence);
  for (double* c : {&p.x, &p.y, &p.z}) *c = std::clamp(*c, -kCoordinateLimit, kCoordinateLimit);
  return p;
}

namespace {
Colour lerp(const Colour& a, const Colour& b, double f) {
  return {a.r + f * (b.r - a.r), a.g + f * (b.g - a.g), a.b + f * (b.b - a.b), a.f + f * (b.f - a.f),
          a.t + f * (b.t - a.t)};
}

Colour entry_colour(const RenderPigment& pigment, const RenderMapEntry& e, Vec3 pattern_point) {
  return e.child < 0 ? e.colour : evaluate_pigment(pigment.children[static_cast<std::size_t>(e.child)], pattern_point);
}

// The two entries around `value`: at or above the last entry, the last alone; otherwise the first entry not below
// the value and the one before it (the same entry when the value equals an entry's or lies below the first).
Colour blend(const RenderPigment& pigment, double value, Vec3 pattern_point) {
  const auto& map = pigment.map;
  std::size_t cur = 0;
  if (value >= map.back().value) cur = map.size() - 1;
  else
    while (value > map[cur].value) ++cur;
  const std::size_t prev = (cur == 0 || value == map[cur].value || value >= map.back().value) ? cur : cur - 1;
  const Colour c = entry_colour(pigment, map[cur], pattern_point);
  if (prev == cur) return c;
  const Colour before = entry_colour(pigment, map[prev], pattern_point);
  const double fraction = (value - map[prev].value) / (map[cur].value - map[prev].value);
  return lerp(before, c, fraction);
}

// average: the map's pigments weighted by their values (Do_Average_Pigments).
Colour average(const RenderPigment& pigment, Vec3 pattern_point) {
  Colour sum{};
  double total = 0.0;
  for (const auto& e : pigment.map) {
    const Colour c = entry_colour(pigment, e, pattern_point);
    sum = {sum.r + c.r * e.value, sum.g + c.g * e.value, sum.b + c.b * e.value, sum.f + c.f * e.value,
           sum.t + c.t * e.value};
    total += e.value;
  }
  return {sum.r / total, sum.g / total, sum.b / total, sum.f / total, sum.t / total};
}
}  // namespace

Colour evaluate_pigment(const RenderPigment& pigment, Vec3 world_point) {
  if (pigment.pattern == PatternKind::solid) return pigment.colour;
  const Vec3 p = to_pattern_space(pigment, world_point);
  if (pigment.pattern == PatternKind::average) return average(pigment, p);
  const double value = apply_wave(pattern_value(pigment.params, p), pigment.wave);
  return blend(pigment, value, p);
}

}  // namespace povtrace::render

// Pigment evaluation (povray-sdl-and-geometry.md §11; POV-Ray 3.7 pigment.cpp Compute_Pigment, warps.cpp
// Warp_EPoint, pattern.cpp Search_Blend_Map).
#include <algorithm>
#include <cmath>

#include "renderer/pattern/pattern_functions.hpp"
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
  // The repeated cell of the black holes: one per evaluation, shared by all of them (POV-Ray's Warp_EPoint keeps
  // the indices of an axis a hole does not repeat on from the hole before).
  int hole_cell[3] = {0, 0, 0};
  for (const PatternStep& s : pigment.steps) {
    if (s.transformed) p = s.pattern_from_world.point(p);
    if (s.turbulence) p = displaced(p, *s.turbulence);
    if (s.repeat) p = repeated(p, *s.repeat);
    if (s.mapping) p = patterns::mapping_warp(p, *s.mapping);
    if (s.black_hole) p = patterns::black_hole_warp(p, *s.black_hole, hole_cell);
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

// A map entry's colour: its own, or its pigment's at the pattern point (found as that pigment reports).
PigmentSample entry_colour(const RenderPigment& pigment, const RenderMapEntry& e, const TexturePoint& at) {
  if (e.child < 0) return {e.colour, true};
  return sample_pigment(pigment.children[static_cast<std::size_t>(e.child)], at);
}

// The map's entries around `value`, blended; found when either is.
PigmentSample blend(const RenderPigment& pigment, double value, const TexturePoint& at) {
  const MapChoice m = choose_entries(pigment.map, value);
  const PigmentSample c = entry_colour(pigment, pigment.map[m.cur], at);
  if (m.prev == m.cur) return c;
  const PigmentSample before = entry_colour(pigment, pigment.map[m.prev], at);
  return {lerp(before.colour, c.colour, m.fraction), c.found || before.found};
}

// average: the map's pigments weighted by their values (Do_Average_Pigments).
Colour average(const RenderPigment& pigment, const TexturePoint& at) {
  Colour sum{};
  double total = 0.0;
  for (const auto& e : pigment.map) {
    const Colour c = entry_colour(pigment, e, at).colour;
    sum = {sum.r + c.r * e.value, sum.g + c.g * e.value, sum.b + c.b * e.value, sum.f + c.f * e.value,
           sum.t + c.t * e.value};
    total += e.value;
  }
  return {sum.r / total, sum.g / total, sum.b / total, sum.f / total, sum.t / total};
}
}  // namespace

PigmentSample sample_pigment(const RenderPigment& pigment, const TexturePoint& at) {
  if (pigment.pattern == PatternKind::solid) return {pigment.colour, true};
  // uv_mapping: the one pigment at the hit's <u, v, 0>, unwarped (Compute_Pigment UV_MAP_PATTERN).
  // It always counts as found, even over an image map used once.
  if (pigment.pattern == PatternKind::uv_mapping)
    return {evaluate_pigment(pigment.children.front(), at.at_uv()), true};
  const TexturePoint p = at.moved(to_pattern_space(pigment, at.point));
  if (pigment.pattern == PatternKind::image_map) {
    const std::optional<Colour> c = image_map_colour(*pigment.image->image, pigment.image->mapping, p.point);
    if (!c) return {kOffImageColour, false};
    return {*c, true};
  }
  if (pigment.pattern == PatternKind::average) return {average(pigment, p), true};
  const double value = apply_wave(pattern_value(pigment.params, p.point, p.surface), pigment.wave);
  return blend(pigment, value, p);
}

double pigment_grey(const RenderPigment& pigment, Vec3 p, const ShadingSurface* surface) {
  TexturePoint at(p);
  at.surface = surface;
  const PigmentSample s = sample_pigment(pigment, at);
  if (!s.found) return 0.0;
  return static_cast<float>(0.297 * s.colour.r + 0.589 * s.colour.g + 0.114 * s.colour.b);
}

}  // namespace povtrace::render

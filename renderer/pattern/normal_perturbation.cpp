#include "renderer/pattern/normal_perturbation.hpp"

#include <array>
#include <cmath>
#include <cstdint>

#include "renderer/pattern/image_map.hpp"
#include "renderer/pattern/pattern_functions.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {
// The four vertices of a regular tetrahedron around the origin (one on +y), at which POV-Ray samples a pattern
// normal's pattern; the decimals are those POV-Ray uses (√(8/9), √(2/9), √(2/3) and 1/3 to nine places).
constexpr std::array<Vec3, 4> kPyramid = {{{0.942809041, -0.333333333, 0.0},
                                           {-0.471404521, -0.333333333, 0.816496581},
                                           {-0.471404521, -0.333333333, -0.816496581},
                                           {0.0, 1.0, 0.0}}};

// Pattern normals: the sum of the tetrahedron's vertices weighted by the pattern there, scaled by
// −5·amount·(0.02/accuracy) — POV-Ray's "fudge factor", which makes the default accuracy 0.02 a plain −5.
constexpr double kSlopeFudge = -5.0;
constexpr double kDefaultAccuracy = 0.02;

Vec3 pattern_slope(const RenderNormal& n, Vec3 p, const ShadingSurface* surface) {
  const double amount = n.amount * kSlopeFudge * (kDefaultAccuracy / n.accuracy);
  Vec3 sum{0, 0, 0};
  for (const Vec3& v : kPyramid) sum += v * (slope_value(n, p + v * n.accuracy, surface) * amount);
  return sum;
}

// ripples: each source's distance d from the point gives a sine of d·frequency + phase; the normal is pushed
// along the direction from the source, the sum averaged over the sources.
Vec3 ripples(const RenderNormal& n, Vec3 p, const std::vector<WaveSource>& waves, bool per_source_frequency) {
  Vec3 sum{0, 0, 0};
  const double count = static_cast<double>(waves.size());
  for (const WaveSource& w : waves) {
    const Vec3 d = p - w.centre;
    double len = length(d);
    if (len == 0.0) len = 1.0;
    const double f = per_source_frequency ? w.frequency : 1.0;
    const double s = cycloidal(len * n.pattern.wave.frequency * f + n.pattern.wave.phase) * n.amount / f;
    sum += d * (s / (len * count));
  }
  return sum;
}

// wrinkles: ten octaves of the absolute vector noise, each at twice the frequency and half the weight.
Vec3 wrinkles(Vec3 p) {
  constexpr int kOctaves = 10;
  Vec3 sum{0, 0, 0};
  double scale = 1.0;
  for (int i = 0; i < kOctaves; ++i, scale *= 2.0) {
    const Vec3 v = vector_noise(p * scale);
    sum += Vec3{std::fabs(v.x / scale), std::fabs(v.y / scale), std::fabs(v.z / scale)};
  }
  return sum;
}

Vec3 displacement(const RenderNormal& n, Vec3 p, const std::vector<WaveSource>& waves,
                  const ShadingSurface* surface) {
  switch (n.kind) {
    case NormalKind::pattern: return pattern_slope(n, p, surface);
    case NormalKind::bumps: return vector_noise(p) * n.amount;
    case NormalKind::dents: {
      const double v = noise(p, n.pattern.params.noise_generator);
      return vector_noise(p) * (v * v * v * n.amount);
    }
    case NormalKind::wrinkles: return wrinkles(p) * n.amount;
    case NormalKind::ripples: return ripples(n, p, waves, false);
    case NormalKind::waves: return ripples(n, p, waves, true);
    case NormalKind::quilted:
      return quilted_offset(p, n.pattern.params.control0, n.pattern.params.control1) * n.amount;
    case NormalKind::bump_map:
    case NormalKind::facets:
    case NormalKind::uv_mapping:
    case NormalKind::average: break;   // perturbed() handles them
  }
  return {0, 0, 0};
}

// POV-Ray's Hermite_Cubic between two slope_map entries (height and slope at each end, t in [0, 1]).
double hermite(double t, const SlopeEntry& a, const SlopeEntry& b) {
  const double t2 = t * t, t3 = t2 * t;
  return a.height * (2 * t3 - 3 * t2 + 1) + a.slope * (t3 - 2 * t2 + t) + b.height * (3 * t2 - 2 * t3) +
         b.slope * (t3 - t2);
}

double slope_map(const std::vector<SlopeEntry>& map, double value) {
  if (map.empty()) return value;
  std::size_t cur = 0;
  if (value >= map.back().value) cur = map.size() - 1;
  else
    while (value > map[cur].value) ++cur;
  if (cur == 0 || value == map[cur].value || value >= map.back().value) return map[cur].height;
  const SlopeEntry& prev = map[cur - 1];
  return hermite((value - prev.value) / (map[cur].value - prev.value), prev, map[cur]);
}

Vec3 normalized_unless(bool keep, Vec3 v) { return keep ? v : normalize(v); }
}  // namespace

double slope_value(const RenderNormal& n, Vec3 p, const ShadingSurface* surface) {
  return slope_map(n.slope_map, apply_wave(pattern_value(n.pattern.params, p, surface), n.pattern.wave));
}

RenderNormal build_render_normal(const Normal& normal, ImageCache* images) {
  RenderNormal r;
  r.kind = normal.kind;
  for (const NormalMapEntry& e : normal.map)
    r.map.push_back({e.value, e.normal ? std::make_shared<const RenderNormal>(build_render_normal(*e.normal, images))
                                       : nullptr});
  if (normal.kind == NormalKind::uv_mapping) {
    r.uv_normal = std::make_shared<RenderNormal>(build_render_normal(*normal.uv_normal, images));
    return r;
  }
  if (normal.kind == NormalKind::bump_map) {
    r.bump = build_render_image(*normal.pattern.image, images);
    r.use_index = normal.pattern.image->use_index;
  }
  Pigment carrier = normal.pattern;
  // The normal-only patterns (and average) evaluate no pattern of their own; the carrier only moves the point (as
  // a pattern with a value would: POV-Ray applies the classic turbulence to every pattern but marble and wood).
  if (normal.kind != NormalKind::pattern) carrier.pattern = PatternKind::bozo;
  r.pattern = build_render_pigment(carrier);
  r.pattern.children.clear();
  r.pattern.map.clear();
  Matrix pattern_from_world;
  for (const PatternStep& s : r.pattern.steps)
    if (s.transformed) pattern_from_world = pattern_from_world * s.pattern_from_world;
  r.transformed = !(pattern_from_world == Matrix::identity());
  r.pattern_from_world = pattern_from_world;
  r.world_from_pattern = pattern_from_world.inverse();
  r.amount = normal.amount;
  r.accuracy = normal.accuracy;
  r.no_bump_scale = normal.no_bump_scale;
  r.slope_map = normal.slope_map;
  r.facets_coords = normal.facets_coords;
  r.facets_size = normal.facets_size;
  r.facets_metric = normal.facets_metric;
  return r;
}

void set_normal_generator(RenderNormal& normal, NoiseGenerator generator) {
  set_generator(normal.pattern, generator);
  if (normal.uv_normal) set_normal_generator(*normal.uv_normal, generator);
  for (RenderNormal::MapEntry& e : normal.map)
    if (e.normal) {
      auto copy = std::make_shared<RenderNormal>(*e.normal);
      set_normal_generator(*copy, generator);
      e.normal = std::move(copy);
    }
}

namespace {
// Warp_Normal: into the normal's pattern space (its transforms), unit length there unless no_bump_scale.
Vec3 warp_normal(const RenderNormal& n, Vec3 v) {
  v = normalized_unless(n.no_bump_scale, v);
  if (n.transformed) v = normalized_unless(n.no_bump_scale, n.world_from_pattern.normal_from_inverse(v));
  return v;
}

// UnWarp_Normal: back out of the pattern space, unit length again unless no_bump_scale.
Vec3 unwarp_normal(const RenderNormal& n, Vec3 v) {
  v = normalized_unless(n.no_bump_scale, v);
  if (n.transformed) v = n.pattern_from_world.normal_from_inverse(v);
  return normalized_unless(n.no_bump_scale, v);
}

Vec3 perturbed(const RenderNormal& n, Vec3 normal, const TexturePoint& at, const std::vector<WaveSource>& waves);

// An entry's normal bends `v` at the pattern-space point of the map's normal; a null one leaves it.
Vec3 entry_perturbed(const RenderNormal::MapEntry& e, Vec3 v, const TexturePoint& at,
                     const std::vector<WaveSource>& waves) {
  return e.normal ? perturbed(*e.normal, v, at, waves) : v;
}

// A normal_map (or list-pattern normals): the pattern's value picks the entries around it, both bend the warped
// normal at the pattern-space point, and the results are blended by the value's position between them, then taken
// back and normalised (Perturb_Normal's blend map branch).
Vec3 mapped(const RenderNormal& n, Vec3 normal, const TexturePoint& at, const std::vector<WaveSource>& waves) {
  const Vec3 p = to_pattern_space(n.pattern, at.point);
  const MapChoice c = choose_entries(n.map, apply_wave(pattern_value(n.pattern.params, p, at.surface), n.pattern.wave));
  const Vec3 v = warp_normal(n, normal);
  const TexturePoint inner = at.moved(p);
  Vec3 result = entry_perturbed(n.map[c.cur], v, inner, waves);
  if (c.prev != c.cur) result = entry_perturbed(n.map[c.prev], v, inner, waves) * (1.0 - c.fraction) + result * c.fraction;
  return normalize(unwarp_normal(n, result));
}

// average: the entries' normals, each bending the warped normal at the pattern-space point, weighted by their
// values and divided by the weights' sum (in single precision, as Do_Average_Normals sums them).
Vec3 averaged(const RenderNormal& n, Vec3 normal, const TexturePoint& at, const std::vector<WaveSource>& waves) {
  const Vec3 v = warp_normal(n, normal);
  const TexturePoint inner = at.moved(to_pattern_space(n.pattern, at.point));
  Vec3 sum{0, 0, 0};
  float total = 0;
  for (const RenderNormal::MapEntry& e : n.map) {
    sum += entry_perturbed(e, v, inner, waves) * e.value;
    total += static_cast<float>(e.value);
  }
  return unwarp_normal(n, sum * (1.0 / static_cast<double>(total)));
}

// POV-Ray's Perturb_Normal, before the caller's normalisation: Warp_Normal, the perturbation, UnWarp_Normal.
// Without no_bump_scale the normal is unit length in pattern space when bent and is normalised again on the way
// back, so scaling a normal scales its bumps with it. A uv-mapped normal is its own normal at the hit's <u, v, 0>.
Vec3 perturbed(const RenderNormal& n, Vec3 normal, const TexturePoint& at, const std::vector<WaveSource>& waves) {
  if (n.uv_normal)
    return normalize(perturbed(*n.uv_normal, normal, at.at_uv(), waves));
  if (n.kind == NormalKind::average) return averaged(n, normal, at, waves);
  if (!n.map.empty()) return mapped(n, normal, at, waves);
  Vec3 v = warp_normal(n, normal);
  const Vec3 p = to_pattern_space(n.pattern, at.point);
  if (n.bump) v = bump_map_normal(*n.bump, n.use_index, n.amount, p, v);
  else if (n.kind == NormalKind::facets) v = patterns::facets(v, p, n.facets_coords, n.facets_size, n.facets_metric);
  else v += displacement(n, p, waves, at.surface);
  return unwarp_normal(n, v);
}
}  // namespace

Vec3 perturb_normal(const RenderNormal& n, Vec3 normal, const TexturePoint& at, const std::vector<WaveSource>& waves) {
  return normalize(perturbed(n, normal, at, waves));
}

Vec3 bump_map_normal(const RenderImageMap& map, bool use_index, double amount, Vec3 pattern_point, Vec3 normal) {
  const MapImage& image = *map.image;
  const ImageMapping& m = map.mapping;
  const auto at = image_position(m, pattern_point);
  if (!at) return normal;
  double x = (*at)[0], y = (*at)[1];
  ImageSample c[3];
  c[0] = image_sample_at(image, m, x, y);
  // One pixel left and up, then one right of that, each wrapped back into the image once.
  x -= 1.0;
  y += 1.0;
  if (x < 0.0) x += m.columns;
  else if (x >= m.columns) x -= m.columns;
  if (y < 0.0) y += m.rows;
  else if (y >= m.rows) y -= m.rows;
  c[1] = image_sample_at(image, m, x, y);
  x += 2.0;
  if (x < 0.0) x += m.columns;
  else if (x >= m.columns) x -= m.columns;
  c[2] = image_sample_at(image, m, x, y);
  const bool grey = !use_index || c[0].index == -1 || c[1].index == -1 || c[2].index == -1;
  double h[3];
  for (int k = 0; k < 3; ++k)
    h[k] = amount * (grey ? static_cast<double>(static_cast<float>(0.297 * c[k].colour.r + 0.589 * c[k].colour.g +
                                                                   0.114 * c[k].colour.b))
                          : static_cast<double>(c[k].index));
  const Vec3 p1{0, h[0], 0}, p2{-1, h[1], 1}, p3{1, h[2], 1};
  const Vec3 bump = normalize(cross(p3 - p2, p1 - p2));
  // The frame around the normal: x across it and y, z completing it (POV-Ray's choice for a normal along y).
  Vec3 yprime = normal;
  Vec3 xprime = cross(yprime, Vec3{0, 1, 0});
  double len = length(xprime);
  if (len < tolerance::epsilon) {
    yprime = std::fabs(normal.y - 1.0) < tolerance::epsilon ? Vec3{0, 1, 0} : Vec3{0, -1, 0};
    xprime = {1, 0, 0};
    len = 1.0;
  }
  xprime = xprime / len;
  const Vec3 zprime = normalize(cross(xprime, yprime));
  return xprime * bump.x + yprime * bump.y - zprime * bump.z;
}

std::vector<WaveSource> make_wave_sources(int count) {
  std::vector<WaveSource> sources;
  std::uint32_t state = static_cast<std::uint32_t>(-560851967);
  constexpr double kUnit = 0.000030518509476;   // 1/32767, as POV-Ray writes it
  constexpr double kLowest = 0.01;
  for (int i = 0; i < count; ++i) {
    const Vec3 d = vector_noise(Vec3{static_cast<double>(i), 0, 0});
    state = state * 1812433253u + 12345u;
    const double bits = static_cast<double>((state >> 16) & 0x7FFFu);
    sources.push_back(WaveSource{normalize(d), bits * kUnit + kLowest});
  }
  return sources;
}

}  // namespace povtrace::render

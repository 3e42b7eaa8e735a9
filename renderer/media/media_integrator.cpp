#include "renderer/media/media_integrator.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "renderer/tracer.hpp"   // evaluate_pigment

namespace povtrace::render {

namespace {
constexpr double kSmallTolerance = 1e-3;   // POV-Ray's SMALL_TOLERANCE: beams ending nearer are not lit
constexpr double kMaxDistance = 1e7;       // POV-Ray's MAX_DISTANCE: where open beams end
constexpr double kEpsilon = 1e-10;

Rgb exp_neg(Rgb a) { return {std::exp(-a.x), std::exp(-a.y), std::exp(-a.z)}; }
double colour_distance(Rgb a, Rgb b) {   // POV-Ray's colourDistance: the sum of the channel differences
  return std::fabs(a.x - b.x) + std::fabs(a.y - b.y) + std::fabs(a.z - b.z);
}

// A light's beam along the segment.
struct LightSpan {
  std::size_t light;
  double s0, s1;
};

// Where the ray is inside a spotlight's cone (POV-Ray's ComputeSpotLightInterval): the roots of the cone's
// quadric along the ray, kept on the cone's open side; a ray starting inside runs from 0.
bool spot_interval(const MediaSegment& seg, const RenderLight& l, double& d1, double& d2) {
  const double cf = l.cos_falloff;
  const double m = 1.0 / (cf * cf);
  const Vec3 v1 = seg.origin - l.light.location;
  const Vec3 axis = l.spot_axis;
  const double k1 = dot(seg.direction, axis), k2 = dot(v1, axis);
  const double len = length(v1);
  const bool inside = len > kEpsilon && k2 / len >= cf;
  if (k1 <= 0.0 && k2 < 0.0) return false;
  const double k3 = dot(v1, seg.direction), k4 = dot(v1, v1);
  const double a = 1.0 - k1 * k1 * m, b = k3 - k1 * k2 * m, c = k4 - k2 * k2 * m;
  if (a == 0.0) {
    if (!inside) return false;
    d1 = 0.0;
    d2 = -c / b;
    return true;
  }
  double d = b * b - a * c;
  if (d > kEpsilon) {
    d = std::sqrt(d);
    double t1 = (-b + d) / a, t2 = (-b - d) / a;
    if (t1 > t2) std::swap(t1, t2);
    const double l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
    if (l1 <= 0.0 && l2 <= 0.0) return false;
    if (l1 <= 0.0) {   // the near root is on the mirrored cone
      if (inside) { t1 = 0.0; t2 = t2 > 0.0 ? t2 : kMaxDistance; }
      else { t1 = t2; t2 = kMaxDistance; }
    } else if (l2 <= 0.0) {
      if (inside) { t2 = t1; t1 = 0.0; }
      else t2 = kMaxDistance;
    }
    d1 = t1;
    d2 = t2;
    return true;
  }
  if (d > -kEpsilon) {
    if (inside) { d1 = 0.0; d2 = -b / a; }
    else { d1 = -b / a; d2 = kMaxDistance; }
    return true;
  }
  return false;
}

// Where the ray is inside a cylindrical light's beam (POV-Ray's ComputeCylinderLightInterval), radius `falloff`.
bool cylinder_interval(const MediaSegment& seg, const RenderLight& l, double& d1, double& d2) {
  const Vec3 v1 = seg.origin - l.light.location;
  const Vec3 axis = l.spot_axis;
  const double k1 = dot(seg.direction, axis), k2 = dot(v1, axis);
  if (k1 <= 0.0 && k2 < 0.0) return false;
  const double a = 1.0 - k1 * k1;
  if (a == 0.0) return false;
  const double k3 = dot(v1, seg.direction), k4 = dot(v1, v1);
  const double b = k3 - k1 * k2, c = k4 - k2 * k2 - l.light.falloff * l.light.falloff;
  double d = b * b - a * c;
  if (!(d > kEpsilon)) return false;
  d = std::sqrt(d);
  double t1 = (-b + d) / a, t2 = (-b - d) / a;
  if (t1 > t2) std::swap(t1, t2);
  const double l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
  if (l1 <= 0.0 && l2 <= 0.0) return false;
  if (l1 <= 0.0) t1 = 0.0;
  else if (l2 <= 0.0) t2 = (kMaxDistance - k2) / k1;
  d1 = t1;
  d2 = t2;
  return true;
}

std::vector<LightSpan> light_spans(const MediaSegment& seg, const std::vector<RenderLight>& lights) {
  std::vector<LightSpan> spans;
  for (std::size_t i = 0; i < lights.size(); ++i) {
    const RenderLight& l = lights[i];
    // POV-Ray's shadowless lights are FILL_LIGHT_SOURCE, which its beam test knows nothing of: they light no media.
    // A light_group's lights are not among the scene's lights that media see.
    if (!l.light.media_interaction || l.light.shadowless || l.light.group >= 0) continue;
    double t1 = 0.0, t2 = seg.depth;
    bool insert = true;
    if (l.light.cylinder || l.light.spotlight) {
      const bool found = l.light.cylinder ? cylinder_interval(seg, l, t1, t2) : spot_interval(seg, l, t1, t2);
      insert = found && t1 < seg.depth && t2 > kSmallTolerance;
    }
    if (insert) spans.push_back({i, std::max(t1, 0.0), std::min(t2, seg.depth)});
  }
  return spans;
}

// POV-Ray's lit intervals from the spans (the variant its 3.7 code uses: starts and ends sorted separately).
std::vector<LitInterval> lit_from_spans(const std::vector<LightSpan>& spans, double depth) {
  std::vector<LitInterval> out;
  if (spans.empty()) return out;
  std::vector<double> s0, s1;
  for (const LightSpan& s : spans) {
    s0.push_back(s.s0);
    s1.push_back(s.s1);
  }
  std::sort(s0.begin(), s0.end());
  std::sort(s1.begin(), s1.end());
  if (s0[0] > 0.0) out.push_back({false, 0.0, s0[0]});
  out.push_back({true, s0[0], s1[0]});
  for (std::size_t i = 1; i < spans.size(); ++i) {
    if (s0[i] > out.back().s1) {
      const double gap_start = out.back().s1;
      out.push_back({false, gap_start, s0[i]});
      out.push_back({true, s0[i], s1[i]});
    } else if (s1[i] > out.back().s1) {
      out.back().s1 = s1[i];
    }
  }
  if (out.back().s1 < depth) {
    const double gap_start = out.back().s1;
    out.push_back({false, gap_start, depth});
  }
  return out;
}

struct SampleInterval {
  bool lit = false;
  double s0 = 0, s1 = 0, ds = 0;
  Rgb od{0, 0, 0}, te{0, 0, 0}, te2{0, 0, 0};
  int samples = 0;
};

// POV-Ray's ComputeMediaSampleInterval: `intervals` of the media with the most, at least one per lit interval;
// a single unlit interval of constant media is sampled as one.
std::vector<SampleInterval> sample_intervals(const std::vector<LitInterval>& lit, const RenderMedia& m) {
  std::vector<SampleInterval> out;
  const std::size_t intervals = std::max(static_cast<std::size_t>(m.intervals), lit.size());
  const auto add = [&](const LitInterval& l, std::size_t n) {
    const double delta = (l.s1 - l.s0) / static_cast<double>(n);
    for (std::size_t j = 0; j < n; ++j) {
      SampleInterval s;
      s.lit = l.lit;
      s.s0 = l.s0 + delta * static_cast<double>(j);
      s.s1 = l.s0 + delta * static_cast<double>(j + 1);
      s.ds = delta;
      out.push_back(s);
    }
  };
  if (lit.size() == 1) {
    add(lit[0], !lit[0].lit && m.constant ? 1 : intervals);
    return out;
  }
  double sum = 0.0;
  for (const LitInterval& l : lit) sum += l.lit ? m.ratio : 1.0 - m.ratio;
  std::size_t remaining = intervals;
  for (std::size_t i = 0; i < lit.size(); ++i) {
    const double weight = lit[i].lit ? m.ratio : 1.0 - m.ratio;
    std::size_t n = static_cast<std::size_t>(weight / sum * static_cast<double>(intervals)) + 1;
    const std::size_t room = remaining - lit.size() + i + 1;
    if (n > room) n = room;
    add(lit[i], n);
    remaining -= n;
  }
  return out;
}

double phase_sum_term(const RenderMedia& m, double alpha) {
  switch (m.scattering_type) {
    // Normalised so that each averages to 1 over the sphere (POV-Ray's constants).
    case 4: return 0.799372013 * (1.0 + alpha * alpha);                                 // Rayleigh
    case 2: return 0.576655375 * (1.0 + 9.0 * std::pow(0.5 * (1.0 + alpha), 8.0));      // Mie hazy
    case 3: return 0.495714547 * (1.0 + 50.0 * std::pow(0.5 * (1.0 + alpha), 32.0));    // Mie murky
    case 5: {                                                                            // Henyey-Greenstein
      const double g = m.eccentricity, g2 = g * g;
      return (1.0 - g2) / std::pow(1.0 + g2 - 2.0 * g * alpha, 1.5);
    }
    default: return 1.0;   // isotropic (and unknown types)
  }
}

class Sampler {
 public:
  Sampler(const MediaList& media, const MediaSegment& seg, MediaLighting& lighting, MediaRandom& random)
      : media_(media), seg_(seg), lighting_(lighting), random_(random) {}

  std::vector<LightSpan> spans;
  bool use_scattering = false;

  // POV-Ray's ComputeOneMediaSample at fraction d0 of `iv`: the sample's emission (with in-scattered light)
  // times the interval length, and its optical depth. Methods 1 and 2 accumulate into the interval.
  void sample(SampleInterval& iv, double d0, int method, Rgb& colour, Rgb& optical_depth) {
    d0 *= iv.ds;
    const double d1 = iv.s0 + d0;
    const Vec3 p = seg_.origin + seg_.direction * d1;
    Rgb extinction{0, 0, 0}, emission{0, 0, 0}, scattering{0, 0, 0};
    for (int i = 0; i < media_.count; ++i) {
      const RenderMedia& m = *media_.items[i];
      const Rgb density = density_at(m, p);
      extinction += density * m.extinction;
      if (!seg_.shadow_ray) {
        emission += density * m.emission;
        scattering += density * m.scattering;
      }
    }
    optical_depth = extinction * iv.ds;
    if (method != 3) iv.od += optical_depth;
    if (!seg_.shadow_ray && use_scattering && iv.lit) {
      for (const LightSpan& s : spans) {
        if (!(d1 >= s.s0 && d1 <= s.s1)) continue;
        if (const auto a = lighting_.arrival(s.light, p)) emission += in_scattered(scattering, *a);
      }
    }
    if (method == 3) emission *= iv.ds;
    else emission = emission * exp_neg(extinction * d0) * iv.ds;
    colour = emission;
    if (method != 3) {
      iv.te += emission;
      iv.te2 += emission * emission;
    }
    ++iv.samples;
  }

  // POV-Ray's ComputeOneMediaSampleRecursive between fractions d1 and d3 with samples c1/od1 and c3/od3.
  void refine(SampleInterval& iv, double d1, double d3, Rgb& result, Rgb c1, Rgb c3, Rgb& od_result, Rgb od1,
              Rgb od3, int depth, double jitter, double threshold) {
    const double d2 = 0.5 * (d1 + d3);
    const double jittered = d2 + jitter * (d3 - d1) * (random_.next() - 0.5);
    Rgb c2, od2;
    sample(iv, jittered, 3, c2, od2);
    if (depth <= 0) {
      result = (c1 + c2 + c3) / 3.0;
      od_result = (od1 + od2 + od3) / 3.0;
      return;
    }
    Rgb sub, od_sub;
    if (colour_distance(c1, c2) > threshold) {
      refine(iv, d1, d2, sub, c1, c2, od_sub, od1, od2, depth - 1, jitter, threshold);
      result = sub / 2.0;
      od_result = od_sub / 2.0;
    } else {
      result = c1 / 3.0 + c2 / 6.0;
      od_result = od1 / 3.0 + od2 / 6.0;
    }
    if (colour_distance(c2, c3) > threshold) {
      refine(iv, d2, d3, sub, c2, c3, od_sub, od2, od3, depth - 1, jitter, threshold);
      result += sub / 2.0;
      od_result += od_sub / 2.0;
    } else {
      result += c2 / 6.0 + c3 / 3.0;
      od_result += od2 / 6.0 + od3 / 3.0;
    }
  }

  double random() { return random_.next(); }

 private:
  static Rgb density_at(const RenderMedia& m, Vec3 p) {
    Rgb c{1, 1, 1};
    for (const RenderPigment& d : m.densities) {
      const Colour s = evaluate_density(d, p);
      c = c * Rgb{s.r, s.g, s.b};
      // Nothing multiplies a zero density back: the densities after it need not be evaluated.
      if (c.x == 0 && c.y == 0 && c.z == 0) break;
    }
    return c;
  }
  static Colour evaluate_density(const RenderPigment& d, Vec3 p) { return evaluate_pigment(d, p); }

  // POV-Ray's ComputeMediaScatteringAttenuation: the phase functions of all media averaged (each counts once,
  // whatever its own scattering), times the total scattering and the light.
  Rgb in_scattered(Rgb scattering, const MediaLighting::Arrival& a) const {
    const double alpha = dot(a.to_light, seg_.direction);
    double k = 0.0;
    for (int i = 0; i < media_.count; ++i) k += phase_sum_term(*media_.items[i], alpha);
    k /= media_.count;
    return scattering * a.colour * k;
  }

  const MediaList& media_;
  const MediaSegment& seg_;
  MediaLighting& lighting_;
  MediaRandom& random_;
};


// Methods 1 and 2 (POV-Ray's ComputeMediaRegularSampling), with method 1's extra samples.
void regular_sampling(Sampler& s, std::vector<SampleInterval>& intervals, const RenderMedia& im, bool constant_shadow,
                      bool shadow_ray) {
  Rgb c, od;
  for (SampleInterval& iv : intervals) {
    for (int j = 0; j < im.min_samples; ++j) {
      if (im.method == 2) {
        const double d0 = (j + 0.5) / im.min_samples + s.random() * im.jitter / im.min_samples;
        s.sample(iv, d0, 2, c, od);
      } else {
        s.sample(iv, s.random(), 1, c, od);   // method 1, or method 3's constant shadow rays
      }
      if (constant_shadow) break;
    }
  }
  if (shadow_ray || im.max_samples <= im.min_samples) return;
  const auto variance_high = [&](const SampleInterval& iv) {
    const double n = 1.0 / iv.samples;
    const Rgb mean = iv.te * n;
    const Rgb va = (iv.te2 * n - mean * mean) * n;
    const double limit = im.sample_threshold[static_cast<std::size_t>(iv.samples - 1)];
    return va.x >= limit || va.y >= limit || va.z >= limit;
  };
  for (SampleInterval& iv : intervals) {
    if (iv.samples >= im.max_samples) continue;
    while (variance_high(iv)) {
      s.sample(iv, s.random(), 1, c, od);
      if (iv.samples > im.max_samples) break;
    }
  }
}

// Method 3 (POV-Ray's ComputeMediaAdaptiveSampling): n = min/2 + 1 (at least 2) points spaced 1/(n+1) of the
// interval from its start, each stretch between neighbours refined recursively and attenuated by the optical depth
// of the stretches before it.
void adaptive_sampling(Sampler& s, std::vector<SampleInterval>& intervals, const RenderMedia& im, double threshold) {
  const int count = std::max(static_cast<int>(im.min_samples / 2.0) + 1, 2);
  const double dd = 1.0 / (count + 1);
  Rgb c0, od0, c1, od1, result, od_result;
  for (SampleInterval& iv : intervals) {
    double d0 = 0.0;
    s.sample(iv, d0 + dd * im.jitter * (s.random() - 0.5), 3, c0, od0);
    iv.te = Rgb{0, 0, 0};
    iv.od = Rgb{0, 0, 0};
    const double n = 1.0 / count;
    d0 += dd;
    for (int j = 1; j <= count; ++j, d0 += dd) {
      s.sample(iv, d0 + dd * im.jitter * (s.random() - 0.5), 3, c1, od1);
      s.refine(iv, d0 - dd, d0, result, c0, c1, od_result, od0, od1, im.aa_level - 1, im.jitter, threshold);
      iv.te += result * exp_neg(iv.od * n);
      c0 = c1;
      iv.od += od_result;
      od0 = od1;
    }
    iv.samples = count;
  }
}
}  // namespace

double MediaRandom::next() {
  // splitmix64
  state_ += 0x9E3779B97F4A7C15ull;
  std::uint64_t z = state_;
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  z ^= z >> 31;
  return static_cast<double>(z >> 11) * 0x1.0p-53;
}

std::uint64_t media_seed(Vec3 origin, Vec3 direction, double depth) {
  std::uint64_t h = 0x6A09E667F3BCC909ull;
  for (double v : {origin.x, origin.y, origin.z, direction.x, direction.y, direction.z, depth}) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h = (h ^ bits) * 0x100000001B3ull;
    h ^= h >> 29;
  }
  return h;
}

std::vector<LitInterval> lit_intervals(const MediaSegment& segment, const std::vector<RenderLight>& lights) {
  std::vector<LitInterval> lit = lit_from_spans(light_spans(segment, lights), segment.depth);
  if (lit.empty()) lit.push_back({false, 0.0, segment.depth});
  return lit;
}

MediaEffect integrate_media(const MediaList& media, const MediaSegment& seg, const std::vector<RenderLight>& lights,
                            MediaLighting& lighting, MediaRandom& random) {
  MediaEffect effect;
  if (media.count == 0) return effect;
  const RenderMedia* im = media.items[0];   // the media with the most intervals sets the sampling
  bool constant_shadow = seg.shadow_ray, use_extinction = false, use_scattering = false;
  double threshold = HUGE_VAL;
  for (int i = 0; i < media.count; ++i) {
    const RenderMedia& m = *media.items[i];
    if (m.intervals > im->intervals) im = &m;
    threshold = std::min(threshold, m.aa_threshold);
    use_extinction = use_extinction || m.use_extinction;
    use_scattering = use_scattering || m.use_scattering;
    constant_shadow = constant_shadow && m.plain_for_shadows;
  }
  if (seg.shadow_ray && !use_extinction) return effect;

  Sampler sampler(media, seg, lighting, random);
  sampler.use_scattering = use_scattering;
  std::vector<LitInterval> lit;
  if (!seg.shadow_ray) {
    sampler.spans = light_spans(seg, lights);
    lit = lit_from_spans(sampler.spans, seg.depth);
  }
  if (lit.empty()) lit.push_back({false, 0.0, seg.depth});
  std::vector<SampleInterval> intervals = sample_intervals(lit, *im);
  if (intervals.front().s0 > 0.0) {
    SampleInterval first;
    first.s1 = first.ds = intervals.front().s0;
    intervals.insert(intervals.begin(), first);
  }
  if (intervals.back().s1 < seg.depth) {
    SampleInterval last;
    last.s0 = intervals.back().s1;
    last.s1 = seg.depth;
    last.ds = seg.depth - last.s0;
    intervals.push_back(last);
  }

  if (im->method == 3 && !constant_shadow) adaptive_sampling(sampler, intervals, *im, threshold);
  else regular_sampling(sampler, intervals, *im, constant_shadow, seg.shadow_ray);

  // POV-Ray's ComputeMediaColour: each interval's mean emission dimmed by the optical depth before it.
  Rgb od{0, 0, 0}, te{0, 0, 0};
  for (const SampleInterval& iv : intervals) {
    const double n = 1.0 / iv.samples;
    te += iv.te * n * exp_neg(od);
    od += iv.od * n;
  }
  effect.transmittance = exp_neg(od);
  effect.emitted = te;
  return effect;
}

}  // namespace povtrace::render

// Small shading steps the tracer's passes share: the camera and light pass (tracer.cpp) and the photon pass
// (photons/photon_trace.cpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>

#include <optional>

#include "renderer/interior_list.hpp"
#include "renderer/render_scene.hpp"

namespace povtrace::render {

inline double max_channel(Rgb c) { return std::max({c.x, c.y, c.z}); }

// Light arriving through a pigment: filter tints by the colour, transmit does not (§3, §4).
inline Rgb pass_through(const Colour& s) { return Rgb{s.r, s.g, s.b} * s.f + Rgb{s.t, s.t, s.t}; }

// Smooth step used by spotlights' falloff zone (§3): 0 below a, 1 at or above b, 3s²−2s³ between.
inline double smoothstep(double a, double b, double x) {
  if (x >= b) return 1.0;
  if (x <= a) return 0.0;
  const double s = (x - a) / (b - a);
  return s * s * (3.0 - 2.0 * s);
}

// Fade of light that crossed `depth` inside an interior on the shadow path (§3) and on a photon's path (POV-Ray's
// PhotonTrace): unlike on the transmitted path, only when fade_power > 0.
inline Rgb shadow_fade(const Interior& in, double depth) {
  if (!(in.fade_power > 0) || !(std::fabs(in.fade_distance) > tolerance::epsilon)) return {1, 1, 1};
  const Rgb fc = rgb_of(in.fade_colour);
  const double d = depth / in.fade_distance;
  if (in.fade_power >= 1000) return {std::exp(-(1 - fc.x) * d), std::exp(-(1 - fc.y) * d), std::exp(-(1 - fc.z) * d)};
  return fc + (Rgb{1, 1, 1} - fc) / (1.0 + std::pow(d, in.fade_power));
}

// A ray crossing the surface of `self` (POV-Ray's ComputeRefraction): the interiors it is in afterwards (`in`,
// updated) and the ratio n_from / n_to it bends by (§4 "Transmission/refraction").
inline double cross_interior(InteriorList& in, const InteriorRef& self) {
  const double ior = self.interior->ior;
  if (in.empty()) {
    in.append(self);
    return 1.0 / ior;
  }
  if (same_interior(in.back(), self)) {
    in.remove(self);
    return in.empty() ? ior : ior / in.back().interior->ior;
  }
  if (in.remove(self)) return 1.0;   // leaving the overlap of two objects: POV-Ray does not bend the ray
  const double eta = in.back().interior->ior / ior;
  in.append(self);
  return eta;
}

// The refracted direction (unit) of `d` through a surface of normal `normal` with ratio `eta` (Heckbert's method,
// as POV-Ray); none on total internal reflection.
inline std::optional<Vec3> refracted_direction(Vec3 d, Vec3 normal, double eta) {
  double m = dot(d, normal);
  const Vec3 facing = m <= 0 ? normal : -normal;
  m = std::fabs(m);
  const double k = 1.0 + eta * eta * (m * m - 1.0);
  if (k < 0) return std::nullopt;
  return normalize(d * eta + facing * (eta * m - std::sqrt(k)));
}

// The mirror direction (unit) of `d` about `normal`, corrected when it would go into the geometric surface (a
// perturbed normal can do that; POV-Ray's ComputeReflection).
inline Vec3 mirror_direction(Vec3 d, Vec3 normal, Vec3 raw_normal) {
  Vec3 r = d - normal * (2.0 * dot(d, normal));
  if (const double n = dot(r, raw_normal); n < 0) {
    if (dot(r, normal) < 0) r = d - raw_normal * (2.0 * dot(d, raw_normal));
    else r = r - raw_normal * (2.0 * n);
  }
  return normalize(r);
}

// A layer's reflection colour and the weight of the ray it reflects.
struct Reflectivity {
  Rgb amount;
  double weight;
};

// POV-Ray's reflectivity of one layer (§4 "Reflection amount"): c = cosine of incidence; `weight`, the weight the
// layer is seen with, is scaled to the reflected ray's weight.
// `single`: the amount rounded as POV-Ray's single-precision colours round it, k·max and (1−k)·min each to float and
// their sum in float (the photon pass needs it: its weights are compared with adc_bailout as floats).
inline Rgb blend_reflection(Rgb hi, Rgb lo, double k, bool single) {
  if (!single) return hi * k + lo * (1.0 - k);
  const auto one = [&](double h, double l) {
    return static_cast<double>(static_cast<float>(static_cast<float>(h * k) + static_cast<float>(l * (1.0 - k))));
  };
  return {one(hi.x, lo.x), one(hi.y, lo.y), one(hi.z, lo.z)};
}

inline Reflectivity reflectivity(const Finish& f, double c, double ior, double weight, bool single = false) {
  const Rgb lo = rgb_of(f.reflection_min), hi = rgb_of(f.reflection_max);
  if (!f.reflection_fresnel) {
    weight *= std::max(max_channel(hi), max_channel(lo));
    const double k = std::fabs(f.reflection_falloff - 1.0) > tolerance::epsilon
                         ? std::pow(1.0 - c, f.reflection_falloff)
                         : 1.0 - c;
    if (std::fabs(k) < tolerance::epsilon) return {lo, weight};
    if (std::fabs(k - 1.0) < tolerance::epsilon) return {hi, weight};
    return {blend_reflection(hi, lo, k, single), weight};
  }
  Rgb r = hi;
  const double g2 = ior * ior + c * c - 1.0;
  if (g2 > 0) {
    const double g = std::sqrt(g2);
    const double a = (g - c) / (g + c);
    const double b = (c * (g + c) - 1.0) / (c * (g - c) + 1.0);
    const double fr = std::clamp(0.5 * a * a * (1.0 + b * b), 0.0, 1.0);
    r = blend_reflection(hi, lo, fr, single);
  }
  weight *= max_channel(r);
  return {r, weight};
}


// The texture point with the hit's uv coordinates when the material reads them.
inline TexturePoint texture_point(const SurfaceHit& hit, Vec3 point, bool uv, double scene_scale) {
  if (!uv) return TexturePoint(point);
  const auto [u, v] = uv_coordinates(hit, point, scene_scale);
  return TexturePoint(point, u, v);
}

// Where a material's textures are evaluated: the hit's <u, v, 0> on a uv-mapped object (POV-Ray's UV_FLAG).
inline TexturePoint material_point(const Material& m, const TexturePoint& at) {
  return m.uv_mapping ? at.at_uv() : at;
}

// 64 random-looking bits from `seed` and the bits of `values` (each folded in, then splitmix64's finalizer).
inline std::uint64_t hash_of_values(std::uint64_t seed, std::initializer_list<double> values) {
  std::uint64_t h = seed;
  for (const double v : values) {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    h ^= bits + 0x9E3779B97F4A7C15ull + (h << 6) + (h >> 2);
    h ^= h >> 30; h *= 0xBF58476D1CE4E5B9ull; h ^= h >> 27; h *= 0x94D049BB133111EBull; h ^= h >> 31;
  }
  return h;
}

// A uniform number in [0, 1] from the bits of a point and a light index.
inline double speckle_random(Vec3 p, std::size_t light) {
  const std::uint64_t h = hash_of_values(0x9E3779B97F4A7C15ull * (light + 1), {p.x, p.y, p.z});
  return static_cast<double>(h >> 11) * (1.0 / 9007199254740991.0);
}
}  // namespace povtrace::render

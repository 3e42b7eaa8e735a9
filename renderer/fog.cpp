// Fog (POV-Ray 3.7's ComputeFog, ComputeConstantFogColour and ComputeGroundFogColour, facts read from
// source/backend/render/trace.cpp, 3.7-stable):
// - Applied to the colour of every ray (camera, reflected, transmitted) that travels outside non-hollow objects,
//   over the ray's whole length to its hit (a miss counts as BOUND_HUGE away), after the colour is computed.
// - Constant fog: attenuation a = exp(−width / distance). Ground fog: the density is 1 below `offset` along `up` and
//   1/(1 + h²) above it, h = (height − offset)/alt; a = exp(−width · mean density / distance), the mean from the
//   integral atan(h) of the density between the ray's two ends.
// - Turbulence thins the fog: width ·= 1 − exp(−width/distance) · min(1, turbulence(p) · turb_depth), p the middle of
//   the ray (scaled per axis by the turbulence vector), with POV-Ray's noise (pattern/noise.hpp).
// - a is at least the fog colour's transmit. Over all fogs: what is behind is scaled by a·((1 − f) + f·colour), and
//   (1 − a)·colour is added; the alpha transmit is scaled by the grey of that attenuation.
#include <algorithm>
#include <cmath>

#include "runtime/noise.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {

double ground_density(const Fog& fog, Vec3 from, Vec3 to) {
  const double start = (dot(from, fog.up) - fog.offset) / fog.alt;
  const double end = (dot(to, fog.up) - fog.offset) / fog.alt;
  if (start <= 0.0) return end <= 0.0 ? 1.0 : (std::atan(end) - start) / (end - start);
  if (end <= 0.0) return (std::atan(start) - end) / (start - end);
  const double delta = start - end;
  if (std::fabs(delta) > tolerance::epsilon) return (std::atan(start) - std::atan(end)) / delta;
  return 1.0 / (start * start + 1.0);
}

// Width of fog along the ray after turbulence thinned it.
double turbulent_width(const Fog& fog, Vec3 middle, double width, NoiseGenerator generator) {
  if (!fog.turbulence) return width;
  const Turbulence& t = *fog.turbulence;
  const Vec3 p{middle.x * t.amount.x, middle.y * t.amount.y, middle.z * t.amount.z};
  const double k = std::exp(-width / fog.distance);
  return width * (1.0 - k * std::min(1.0, turbulence(p, t, generator) * fog.turb_depth));
}

double fog_attenuation(const Fog& fog, const Ray& ray, double width, NoiseGenerator generator) {
  if (fog.type == 2) {
    const Vec3 end = ray.origin + ray.direction * width;
    const double density = ground_density(fog, ray.origin, end);
    width = turbulent_width(fog, (ray.origin + end) * 0.5, width, generator);
    return std::exp(-width * density / fog.distance);
  }
  width = turbulent_width(fog, ray.origin + ray.direction * (width / 2.0), width, generator);
  return std::exp(-width / fog.distance);
}

}  // namespace

// A shadow ray's fog only dims the light: POV-Ray adds no fog colour to shadow test rays.
Rgb Tracer::fog_on_shadow(const Ray& ray, double depth) const {
  Rgb total_attenuation{1, 1, 1};
  for (const Fog& fog : scene_.fogs) {
    if (!(std::fabs(fog.distance) > tolerance::epsilon)) continue;
    const double a = std::max(fog_attenuation(fog, ray, depth, scene_.noise_generator), fog.colour.t);
    const Rgb c{fog.colour.r, fog.colour.g, fog.colour.b};
    const Rgb through = Rgb{1 - fog.colour.f, 1 - fog.colour.f, 1 - fog.colour.f} + c * fog.colour.f;
    total_attenuation = Rgb{total_attenuation.x * a * through.x, total_attenuation.y * a * through.y,
                            total_attenuation.z * a * through.z};
  }
  return total_attenuation;
}

Radiance Tracer::with_fog(const Ray& ray, double depth, Radiance r) const {
  Rgb total_attenuation{1, 1, 1};
  Rgb total_colour{0, 0, 0};
  for (const Fog& fog : scene_.fogs) {
    if (!(std::fabs(fog.distance) > tolerance::epsilon)) continue;
    double a = fog_attenuation(fog, ray, depth, scene_.noise_generator);
    a = std::max(a, fog.colour.t);
    const Rgb c{fog.colour.r, fog.colour.g, fog.colour.b};
    const Rgb through = Rgb{1 - fog.colour.f, 1 - fog.colour.f, 1 - fog.colour.f} + c * fog.colour.f;
    total_attenuation = Rgb{total_attenuation.x * a * through.x, total_attenuation.y * a * through.y,
                            total_attenuation.z * a * through.z};
    total_colour += c * (1.0 - a);
  }
  r.colour = total_colour + Rgb{total_attenuation.x * r.colour.x, total_attenuation.y * r.colour.y,
                                total_attenuation.z * r.colour.z};
  r.transmit *= grey(total_attenuation);
  return r;
}

}  // namespace povtrace::render

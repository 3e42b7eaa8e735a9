// Pattern dispatch, the geometric patterns and the wave step (pattern.cpp Evaluate_TPat in POV-Ray 3.7).
#include "renderer/pattern/pattern.hpp"
#include "renderer/pattern/image_map.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "runtime/function_value.hpp"

#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render {

namespace {
// POV-Ray's CLIP_DENSITY for the distance patterns: 1 at the centre falling to 0 at distance 1, 0 beyond
// (and 1 for a negative distance, which cannot happen here).
double fall_off(double r) { return r < 0.0 ? 1.0 : r > 1.0 ? 0.0 : 1.0 - r; }

// gradient: P·V̂, folded into [0, 1] only above 1 (negative values are wrapped by the wave step).
double gradient(Vec3 p, Vec3 direction) {
  const double d = dot(p, direction);
  return d > 1.0 ? std::fmod(d, 1.0) : d;
}

// radial: the angle around the y axis as a fraction of a turn (atan2(x, z), so 0.5 along −z and 0.75 along +z),
// offset by a quarter turn; POV-Ray returns 0.25 within 0.001 of the axis.
double radial(Vec3 p) {
  constexpr double kAxisZone = 0.001;
  if (std::fabs(p.x) < kAxisZone && std::fabs(p.z) < kAxisZone) return 0.25;
  return 0.25 + (std::atan2(p.x, p.z) + std::numbers::pi) / (2.0 * std::numbers::pi);
}

// POV-Ray's FLOOR macro: floor, except that an exact negative integer n gives n − 1.
double pov_floor(double x) { return x >= 0.0 ? std::floor(x) : 0.0 - std::floor(0.0 - x) - 1.0; }

double quilted(Vec3 p, double control0, double control1) {
  const Vec3 v = quilted_offset(p, control0, control1);
  return (std::fabs(v.x) + std::fabs(v.y) + std::fabs(v.z)) / 3.0;
}

double leopard(Vec3 p) {
  const double mean = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
  return mean * mean;
}

}  // namespace

double patterns::triangle_wave(double v) {
  // POV-Ray's Triangle_Wave forms a negative value's offset as v + 1 + floor(|v|), which rounds differently.
  const double offset = v >= 0.0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
  return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

// The offset from the unit cell's centre (cells split by POV-Ray's FLOOR), scaled by a cubic Bézier of its length
// (ends 0 and 1, inner controls control0 and control1, times POV-Ray's 1.154700538 ≈ 2/√3): quilt_cubic.
Vec3 quilted_offset(Vec3 p, double control0, double control1) {
  constexpr double kScale = 1.154700538;
  const Vec3 v{p.x - pov_floor(p.x) - 0.5, p.y - pov_floor(p.y) - 0.5, p.z - pov_floor(p.z) - 0.5};
  const double t = std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z);
  const double it = 1 - t, it2 = it * it, t2 = t * t, t3 = t * t2;
  const double s = (t3 + 3.0 * t * it2 * control0 + 3.0 * t2 * it * control1) * kScale;
  return {v.x * s, v.y * s, v.z * s};
}

double cycloidal(double v) {
  // POV-Ray scales the fractional part by 50000 and back before the sine; kept for identical rounding.
  constexpr double kSteps = 50000.0;
  const double two_pi = 2.0 * std::numbers::pi;
  if (v >= 0.0) return std::sin(((v - std::floor(v)) * kSteps) / kSteps * two_pi);
  const double f = -(v + std::floor(-v));
  return -std::sin((f * kSteps) / kSteps * two_pi);
}

// POV-Ray's function pattern: the function's value, values above 1 wrapped by fmod (negative ones go on to the
// wave step, which wraps them). A value that is not a number (0/0 in the function) is taken as 0: POV-Ray's map
// lookup then depends on how NaN compares.
namespace {
double function_pattern(const sdl::FunctionValue& f, int noise_generator, Vec3 p) {
  const double args[3] = {p.x, p.y, p.z};
  const double v = sdl::evaluate_function(f, args, nullptr, noise_generator);
  if (std::isnan(v)) return 0.0;
  return v > 1.0 ? std::fmod(v, 1.0) : v;
}
}  // namespace

double pattern_value(const PatternParams& params, Vec3 p, const ShadingSurface* hit) {
  switch (params.kind) {
    case PatternKind::checker: return patterns::checker(p);
    case PatternKind::hexagon: return patterns::hexagon(p);
    case PatternKind::brick: return patterns::brick(p, params.brick_size, params.mortar);
    case PatternKind::gradient: return gradient(p, params.gradient);
    case PatternKind::radial: return radial(p);
    case PatternKind::onion: return std::fmod(length(p), 1.0);
    case PatternKind::planar: return fall_off(std::fabs(p.y));
    case PatternKind::boxed: return fall_off(std::max({std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)}));
    case PatternKind::spherical: return fall_off(length(p));
    case PatternKind::cylindrical: return fall_off(std::sqrt(p.x * p.x + p.z * p.z));
    case PatternKind::leopard: return leopard(p);
    case PatternKind::bozo:
    case PatternKind::spotted: return noise(p, params.noise_generator);
    case PatternKind::granite: return patterns::granite(p, params.noise_generator);
    case PatternKind::marble: return patterns::marble(p, params.turbulence, params.noise_generator);
    case PatternKind::wood: return patterns::wood(p, params.turbulence);
    case PatternKind::agate:
      return patterns::agate(p, params.turbulence.value_or(Turbulence{}), params.agate_turb, params.noise_generator);
    case PatternKind::crackle: return patterns::crackle(p, params.crackle, params.noise_generator);
    case PatternKind::cells: return patterns::cells(p);
    case PatternKind::bumps: return noise(p, params.noise_generator);
    case PatternKind::dents: return patterns::dents(p, params.noise_generator);
    case PatternKind::wrinkles: return patterns::wrinkles(p, params.noise_generator);
    // POV-Ray applies frequency and phase inside these two and once more in the wave step.
    case PatternKind::ripples: return patterns::ripples(p, params.frequency, params.phase);
    case PatternKind::waves: return patterns::waves(p, params.frequency, params.phase);
    case PatternKind::function: return function_pattern(*params.function, params.function_noise_generator, p);
    case PatternKind::quilted: return quilted(p, params.control0, params.control1);
    case PatternKind::spiral1: return patterns::spiral1(p, params.arms, params.turbulence, params.noise_generator);
    case PatternKind::spiral2: return patterns::spiral2(p, params.arms, params.turbulence, params.noise_generator);
    case PatternKind::mandel:
    case PatternKind::julia:
    case PatternKind::magnet: return patterns::fractal(params.fractal, p);
    case PatternKind::slope: return patterns::slope(params.slope, p, hit);
    case PatternKind::aoi: return patterns::aoi(hit);
    case PatternKind::pigment_pattern: return pigment_grey(*params.pigment, p, hit);
    // POV-Ray's object_pattern: Inside_Object at the pattern-space point.
    case PatternKind::object: return params.object && params.object->inside(p) ? 1.0 : 0.0;
    case PatternKind::density_file:
      return patterns::density_file(*params.density_file, params.density_interpolation, p);
    case PatternKind::image_pattern: return image_pattern_value(*params.image, p);
    case PatternKind::solid:
    case PatternKind::average:
    case PatternKind::image_map:
    case PatternKind::material_map:        // textures only: texture_pattern_value
    case PatternKind::uv_mapping: break;   // no pattern value: evaluate_pigment handles them
  }
  return 0.0;
}

// fmod by 1.00001 (not 1) keeps an exact 1.0 at 1.0, so the last map entry is reachable; negative values (a
// negative frequency or gradient) wrap into [0, 1).
double apply_wave(double value, const WaveParams& w) {
  constexpr double kWrap = 1.00001;
  if (w.frequency != 0.0) value = std::fmod(value * w.frequency + w.phase, kWrap);
  if (value < 0.0) value -= std::floor(value);
  switch (w.wave) {
    case WaveType::ramp: return value;
    case WaveType::sine: return (1.0 + cycloidal(value)) * 0.5;
    case WaveType::triangle: return patterns::triangle_wave(value);
    case WaveType::scallop: return std::fabs(cycloidal(value * 0.5));
    case WaveType::cubic: return value * value * (3.0 - 2.0 * value);
    case WaveType::poly: return std::pow(value, w.exponent);
  }
  return value;
}

}  // namespace povtrace::render

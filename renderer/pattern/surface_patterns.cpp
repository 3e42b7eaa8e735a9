// slope and aoi: patterns of the surface being shaded rather than of the point alone (POV-Ray 3.7 pattern.cpp
// slope_pattern, aoi_pattern). Both read the world-space normal POV-Ray calls PNormal; away from a surface (a media
// density, a function) there is none and the value is 0, as in POV-Ray.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "scene/pov_vector_math.hpp"
#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render::patterns {

namespace {
constexpr double kPovEpsilon = 1e-10;   // POV-Ray's EPSILON

// A component of v along an axis given as ±(1 + index), or 0 for none (the exact unit-axis shortcut POV-Ray takes,
// which also decides the rounding).
double along(Vec3 v, int axis, Vec3 direction) {
  if (axis > 0) return v[axis - 1];
  if (axis < 0) return -v[-axis - 1];
  return dot(v, direction);
}

// Values of exactly 1 stay just below it instead of wrapping to the bottom of the map; everything else wraps into
// [0, 1) (negative values from the top).
double wrap_unit(double v) {
  if (v == 1.0) return v - kPovEpsilon;
  return v < 0.0 ? 1.0 + std::fmod(v, 1.0) : std::fmod(v, 1.0);
}
}  // namespace

double slope(const SlopeParams& s, Vec3 p, const ShadingSurface* hit) {
  if (!hit) return 0.0;
  double cosine;
  if (s.point_at) cosine = dot(hit->normal, pov_normalized(s.direction - hit->point));
  else cosine = along(hit->normal, s.slope_axis, s.direction);
  cosine = std::clamp(cosine, -1.0, 1.0);
  // The angle above the plane normal to the direction, from −90° to 90°, as 0 … 1.
  double value1 = std::asin(cosine) / std::numbers::pi * 2;
  value1 = (value1 + 1.0) * 0.5;
  if (s.slope_range != 0.0) value1 = (value1 - s.slope_low) / s.slope_range;
  if (s.altitude_weight == 0.0) return wrap_unit(value1);

  double value2 = along(p, s.altitude_axis, s.altitude);
  if (s.altitude_range != 0.0) value2 = (value2 - s.altitude_low) / s.altitude_range;
  const double value = s.slope_weight * value1 + s.altitude_weight * value2;
  if (value - 1.0 < kPovEpsilon && value >= 1.0) return value - kPovEpsilon;
  return value < 0.0 ? 1.0 + std::fmod(value, 1.0) : std::fmod(value, 1.0);
}

// The angle between the normal and the ray, 0 (along the ray) … 1 (against it).
double aoi(const ShadingSurface* hit) {
  if (!hit) return 0.0;
  const double c = std::clamp(dot(pov_normalized(hit->normal), pov_normalized(hit->ray_direction)), -1.0, 1.0);
  return std::acos(c) / std::numbers::pi;
}

}  // namespace povtrace::render::patterns

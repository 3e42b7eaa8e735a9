// POV-Ray's own roundings of two vector operations, for the places where povtrace must agree with it to the last
// bit (camera rays, pattern directions that decide exact-axis shortcuts).
#pragma once

#include <cmath>

#include "scene/vecmath.hpp"

namespace povtrace {

// VNormalize / VNormalizeEq: scaled by the reciprocal of the length, not divided by it.
inline Vec3 pov_normalized(Vec3 v) { return v * (1.0 / std::sqrt(dot(v, v))); }

// M_PI_360 as POV-Ray's source spells it.
inline constexpr double kPovPiOver360 = 0.00872664625997164788;

}  // namespace povtrace

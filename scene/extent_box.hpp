// POV-Ray's bounding box (BBOX) as the SDL sees it through min_extent() and max_extent(): a lower corner and
// lengths held in single precision (BBOX_VAL is a float), with the operations POV-Ray applies to it when objects
// are made, transformed, clipped and combined. Plain data in the scene description; the renderer builds its own
// bounds and never reads these.
#pragma once

#include <array>

#include "vecmath.hpp"

namespace povtrace {

inline constexpr double kBoundHuge = 2.0e10;       // POV-Ray's BOUND_HUGE
inline constexpr double kCriticalLength = 1.0e6;   // CRITICAL_LENGTH: wider CSG and quadric boxes become the huge box

struct ExtentBox {
  std::array<float, 3> lower{}, lengths{};

  // Make_BBox: each value rounded to float.
  static ExtentBox make(Vec3 lower, Vec3 lengths);
  // Make_BBox_from_min_max: the lengths are the double differences, then rounded.
  static ExtentBox from_min_max(Vec3 lo, Vec3 hi);
  // The box of an unbounded object: ±BOUND_HUGE/2.
  static ExtentBox huge();

  Vec3 lo() const { return {lower[0], lower[1], lower[2]}; }
  // Make_min_max_from_BBox on doubles: the lower corner plus the lengths.
  Vec3 hi() const {
    return {double(lower[0]) + lengths[0], double(lower[1]) + lengths[1], double(lower[2]) + lengths[2]};
  }
  // max_extent(): the float sum, as POV-Ray's Parse_Float_Or_Vector computes it.
  Vec3 max_extent() const { return {lower[0] + lengths[0], lower[1] + lengths[1], lower[2] + lengths[2]}; }
  // BOUNDS_VOLUME: the product of the float lengths, in float.
  double volume() const { return lengths[0] * lengths[1] * lengths[2]; }
  bool wider_than_critical() const {
    return lengths[0] > kCriticalLength || lengths[1] > kCriticalLength || lengths[2] > kCriticalLength;
  }

  // Recompute_BBox: the box of the 8 transformed corners, clipped to ±BOUND_HUGE/2.
  ExtentBox transformed(const Matrix& m) const;
};

}  // namespace povtrace

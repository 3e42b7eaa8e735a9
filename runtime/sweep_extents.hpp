// The profile math of lathe, prism and sor that their bounding boxes (min_extent() and max_extent(), in the
// parser) and their intersection data (renderer/shapes/sweep_build.cpp) are both built from, as POV-Ray 3.7 computes
// it at parse time (source/backend/shape/lathe.cpp Compute_Lathe, prism.cpp Compute_Prism, sor.cpp Compute_Sor and
// each Compute_BBox, 3.7-stable; read for the behaviour only):
// - A segment's x and y are cubics in w ∈ [0, 1] built from a window of points: linear (P0 → P1), quadratic (from P1
//   to P2, slope (P2 − P0)/2 at P1), cubic (Catmull-Rom from P1 to P2) or Bézier (P0 … P3; a prism's Bézier segment
//   runs backwards, from P3 at w = 0 to P0 at w = 1).
// - A segment's range of each coordinate: its end points' values (a Bézier segment: all four control points), plus
//   for quadratic and cubic segments the values where the derivative vanishes inside [0, 1].
// - A conic prism's rectangles are scaled by both heights.
// - The sor's segment k is r² = a·y³ + b·y² + c·y + d through points k+1 and k+2, with the slopes of r² there taken
//   from the neighbouring points (2·r·Δr/Δy); its radius range is the end radii and √r² at the turning points of r²
//   between its heights.
// Plain parse-time data: no renderer code.
#pragma once

#include <algorithm>
#include <array>
#include <vector>

#include "scene/extent_box.hpp"
#include "scene/sweep_description.hpp"

namespace povtrace {

// A cubic in the segment parameter w ∈ [0, 1], highest power first: ((c0·w + c1)·w + c2)·w + c3.
using Cubic = std::array<double, 4>;
inline double evaluate(const Cubic& c, double w) { return ((c[0] * w + c[1]) * w + c[2]) * w + c[3]; }

// One lathe or prism profile segment: the point (x(w), y(w)) (a prism's y is the outline's z).
struct ProfileSegment {
  Cubic x{}, y{};
};

// A range of values, empty (lo > hi) until something is added, as POV-Ray starts its ranges at ±BOUND_HUGE. Values
// are taken with std::min and std::max as POV-Ray takes them, so a NaN never enters a range.
struct ValueRange {
  double lo = kBoundHuge, hi = -kBoundHuge;
  void add(double v) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // POV-Ray's running range of a whole profile: the least of the segments' lower ends, the greatest upper end.
  void add(const ValueRange& r) {
    lo = std::min(lo, r.lo);
    hi = std::max(hi, r.hi);
  }
};

// A lathe or prism segment with the ranges of its two coordinates over w ∈ [0, 1].
struct BoundedSegment {
  ProfileSegment curve;
  ValueRange x, y;
};

// The ranges of a whole profile.
struct ProfileRanges {
  ValueRange x, y;
};
ProfileRanges profile_ranges(const std::vector<BoundedSegment>& segments);

// The segments of a lathe's profile, in order (a Bézier profile: one per four points).
std::vector<BoundedSegment> lathe_segments(const Lathe& lathe);

// The segments of a prism's outline, one per segment start, unscaled by a conic sweep.
std::vector<BoundedSegment> prism_segments(const Prism& prism);
// A conic prism's side of a rectangle: the range of the products of its ends with both heights.
ValueRange scaled_by_heights(const ValueRange& r, double height1, double height2);
// The prism's rectangle in the x-z plane (x, and z as y) from its outline's ranges: those ranges for a linear
// sweep, each scaled by both heights for a conic one.
ProfileRanges prism_rectangle(const Prism& prism, const ProfileRanges& outline);

// A sor segment: r² = ((a·y + b)·y + c)·y + d between its heights.
struct SorSegment {
  double a = 0, b = 0, c = 0, d = 0;
};
inline double radius_squared(const SorSegment& s, double y) { return ((s.a * y + s.b) * y + s.c) * y + s.d; }

// A sor segment with its radius range (NaN where r² is negative at a turning point, as POV-Ray leaves it; see
// sweep_extents.cpp) and its heights.
struct BoundedSorSegment {
  SorSegment cubic;
  ValueRange radius, height;
};
// The N − 3 segments of a sor (the parser has checked the heights the slopes divide by).
std::vector<BoundedSorSegment> sor_segments(const Sor& sor);
// The ranges of the whole sor: x the radius, y the height.
ProfileRanges sor_ranges(const std::vector<BoundedSorSegment>& segments);

// The boxes POV-Ray's Compute_BBox makes for each shape before carrying them by the object's transform: the
// caller applies .transformed(world_from_object) (POV-Ray always does, even for the identity, and min_extent()
// reports the result). A lathe or sor: the square of side 2·max radius about the y axis between its heights (a
// lathe whose radii are all negative gets negative lengths, which the transformation turns round); a prism: its
// outline's rectangle (scaled by the heights for a conic sweep) between its heights.
ExtentBox lathe_local_box(const Lathe& lathe);
ExtentBox sor_local_box(const Sor& sor);
ExtentBox prism_local_box(const Prism& prism);

}  // namespace povtrace

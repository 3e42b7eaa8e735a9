// What lathe, prism and sor keep once built (sweep_build.cpp builds it, lathe.cpp, prism.cpp and sor.cpp intersect
// it): POV-Ray's per-segment cubic polynomials of the profile, each segment's bounds, and the bounding rings of
// POV-Ray's bcyl.cpp that decide which lathe and sor segments a ray is tested against (bounding_rings.cpp). The
// polynomials and ranges themselves come from runtime/sweep_extents.hpp, which the parser's min_extent() and
// max_extent() of these shapes are computed from too.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <vector>

#include "scene/description.hpp"
#include "runtime/sweep_extents.hpp"
#include "renderer/geometry.hpp"
#include "renderer/shapes/local_ray.hpp"

namespace povtrace::render {

// A segment's cubics in w ∈ [0, 1] (Cubic, evaluate) and profile segments (ProfileSegment: the point (x(w), y(w))),
// as runtime/sweep_extents.hpp defines them.
using povtrace::Cubic;
using povtrace::evaluate;
using povtrace::ProfileSegment;
inline double derivative(const Cubic& c, double w) { return (3.0 * c[0] * w + 2.0 * c[1]) * w + c[2]; }

// A segment's bounding ring: radii r1 ≤ r ≤ r2 (as computed, so possibly negative: POV-Ray squares them) and
// heights h1 ≤ y ≤ h2.
struct Ring {
  double r1 = 0, r2 = 0, h1 = 0, h2 = 0;
};
// Whether POV-Ray's Intersect_BCyl lists the ring's segment for the object-space ray p + t·d (d unit length).
bool ring_reached(const Ring& ring, Vec3 p, Vec3 d);

// Where on a profile segment a 2-D point lies (for normals asked for by point only, without the hit's segment and
// w): the w of the segment's point nearest to (u, v) among those sharing its u or its v, and that distance. With
// `radial`, the segment's x counts by its magnitude (a lathe's radius).
struct ProfileSpot {
  double w = 0;
  double distance = tolerance::bound_huge;
};
ProfileSpot nearest_spot(const ProfileSegment& s, double u, double v, bool radial);

// Hit parts other than a profile segment (whose element is the segment's index).
inline constexpr std::uint32_t base_element = 0xfffffffeu;   // the disc at the lower height
inline constexpr std::uint32_t cap_element = 0xffffffffu;    // the disc at the upper height

struct LatheData : ShapeData {
  SplineKind spline = SplineKind::linear;
  bool sturm = false;
  std::vector<ProfileSegment> segments;
  std::vector<Ring> rings;
  double radius1 = 0, radius2 = 0, height1 = 0, height2 = 0;   // the whole profile's extent
};

// A prism segment: its curve, and its bounding rectangle in the outline plane (x1…x2, z1…z2, scaled over the
// heights for a conic sweep) and unscaled (u2, v1…v2) for the inside test.
struct PrismSegment {
  ProfileSegment curve;
  double x1 = 0, x2 = 0, z1 = 0, z2 = 0;
  double u2 = 0, v1 = 0, v2 = 0;
};

struct PrismData : ShapeData {
  SplineKind spline = SplineKind::linear;
  bool conic = false, closed = true, sturm = false, degenerate = false;
  double height1 = 0, height2 = 1;
  std::vector<PrismSegment> segments;
  double x1 = 0, x2 = 0, z1 = 0, z2 = 0;   // the whole outline's rectangle (scaled for a conic sweep)
  double u1 = 0, u2 = 0, v1 = 0, v2 = 0;   // the same, unscaled
};

// A sor segment: r² = ((a·y + b)·y + c)·y + d (radius_squared) for heights h1 ≤ y ≤ h2 (its ring's).
using povtrace::radius_squared;
using povtrace::SorSegment;

struct SorData : ShapeData {
  bool closed = true, sturm = false;
  std::vector<SorSegment> segments;
  std::vector<Ring> rings;
  double radius2 = 0, height1 = 0, height2 = 0;
  double base_radius2 = 0, cap_radius2 = 0;
};

std::shared_ptr<LatheData> lathe_data(const Lathe& l);
std::shared_ptr<PrismData> prism_data(const Prism& p);
std::shared_ptr<SorData> sor_data(const Sor& s);

}  // namespace povtrace::render

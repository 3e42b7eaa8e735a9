// Builds lathe, prism and sor data from their descriptions as POV-Ray 3.7 does at parse time (source/backend/shape/
// lathe.cpp Compute_Lathe, prism.cpp Compute_Prism, sor.cpp Compute_Sor, 3.7-stable; read for the behaviour only).
// The segment polynomials and their ranges come from runtime/sweep_extents.hpp (shared with the parser's
// min_extent() and max_extent()); here they become what the intersection code reads: a lathe or sor segment's
// bounding ring, a prism segment's rectangle (scaled over the heights for a conic sweep) with its unscaled bounds
// for the inside test, the whole profile's extent, and the sor's end discs' squared radii from the first and last
// segment, at least 0.
#include "runtime/sweep_extents.hpp"
#include "renderer/shapes/sweep.hpp"

namespace povtrace::render {

std::shared_ptr<LatheData> lathe_data(const Lathe& l) {
  auto d = std::make_shared<LatheData>();
  d->spline = l.spline;
  d->sturm = l.sturm;
  const std::vector<BoundedSegment> segments = lathe_segments(l);
  for (const BoundedSegment& s : segments) {
    d->segments.push_back(s.curve);
    d->rings.push_back(Ring{s.x.lo, s.x.hi, s.y.lo, s.y.hi});
  }
  const ProfileRanges r = profile_ranges(segments);
  d->radius1 = r.x.lo, d->radius2 = r.x.hi, d->height1 = r.y.lo, d->height2 = r.y.hi;
  return d;
}

namespace {
// A prism segment's rectangle in the x-z plane and its unscaled bounds.
PrismSegment prism_segment(const Prism& pr, const BoundedSegment& s) {
  PrismSegment p;
  p.curve = s.curve;
  const ValueRange x = pr.conic ? scaled_by_heights(s.x, pr.height1, pr.height2) : s.x;
  const ValueRange z = pr.conic ? scaled_by_heights(s.y, pr.height1, pr.height2) : s.y;
  p.x1 = x.lo, p.x2 = x.hi, p.z1 = z.lo, p.z2 = z.hi;
  p.u2 = s.x.hi, p.v1 = s.y.lo, p.v2 = s.y.hi;
  return p;
}
}  // namespace

std::shared_ptr<PrismData> prism_data(const Prism& pr) {
  auto d = std::make_shared<PrismData>();
  d->spline = pr.spline;
  d->conic = pr.conic;
  d->closed = !pr.open;
  d->sturm = pr.sturm;
  d->degenerate = pr.degenerate;
  d->height1 = pr.height1;
  d->height2 = pr.height2;
  const std::vector<BoundedSegment> segments = prism_segments(pr);
  for (const BoundedSegment& s : segments) d->segments.push_back(prism_segment(pr, s));
  const ProfileRanges outline = profile_ranges(segments);
  const ProfileRanges rectangle = prism_rectangle(pr, outline);
  d->u1 = outline.x.lo, d->u2 = outline.x.hi, d->v1 = outline.y.lo, d->v2 = outline.y.hi;
  d->x1 = rectangle.x.lo, d->x2 = rectangle.x.hi, d->z1 = rectangle.y.lo, d->z2 = rectangle.y.hi;
  return d;
}

std::shared_ptr<SorData> sor_data(const Sor& so) {
  auto d = std::make_shared<SorData>();
  d->closed = !so.open;
  d->sturm = so.sturm;
  const std::vector<BoundedSorSegment> segments = sor_segments(so);
  for (const BoundedSorSegment& s : segments) {
    d->segments.push_back(s.cubic);
    d->rings.push_back(Ring{s.radius.lo, s.radius.hi, s.height.lo, s.height.hi});
  }
  const ProfileRanges r = sor_ranges(segments);
  d->radius2 = r.x.hi, d->height1 = r.y.lo, d->height2 = r.y.hi;
  auto at_least_zero = [](double v) { return v < 0.0 ? 0.0 : v; };
  d->cap_radius2 = at_least_zero(radius_squared(segments.back().cubic, segments.back().height.hi));
  d->base_radius2 = at_least_zero(radius_squared(segments.front().cubic, segments.front().height.lo));
  return d;
}

}  // namespace povtrace::render

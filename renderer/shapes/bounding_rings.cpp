// Which lathe and sor segments a ray is tested against: POV-Ray 3.7's bounding cylinders (source/backend/bounding/
// bcyl.cpp Intersect_BCyl, 3.7-stable; read for the behaviour only). Each segment is bounded by a thick ring: the
// solid between the cylinders of its two radii (compared squared, so a negative radius counts as positive; a
// cylinder whose squared radius is at most 1e-10 is not tested) and the planes of its two heights. The ray's
// crossings of the ring's boundary are counted: the two discs where the squared radius at the crossing lies
// between the squared radii (only when |d.y| > 1e-10), and each cylinder's two crossings (only when the
// discriminant is positive) at heights within the ring's. Then
// - no crossing: the segment is skipped;
// - two or four: tested when the farthest one lies beyond 1e-10 (POV-Ray's cascade comes to that);
// - any other number: tested (POV-Ray cannot tell where the ray enters and assumes it starts inside).
// POV-Ray also sorts the segments by where the ray enters their rings, to stop once a hit is nearer than the next
// ring; rings contain their segments' surfaces, so that changes no nearest hit and is not done here.
#include <algorithm>
#include <cmath>

#include "renderer/shapes/sweep.hpp"

namespace povtrace::render {

bool ring_reached(const Ring& ring, Vec3 p, Vec3 d) {
  const double a = d.x * d.x + d.z * d.z;
  const double b = p.x * d.x + p.z * d.z;
  const double c = p.x * p.x + p.z * p.z;
  const double inner2 = ring.r1 * ring.r1, outer2 = ring.r2 * ring.r2;
  int count = 0;
  double farthest = -tolerance::bound_huge;
  auto add = [&](double t) { ++count, farthest = std::max(farthest, t); };
  if (d.y < -tolerance::epsilon || d.y > tolerance::epsilon) {
    for (const double h : {ring.h2, ring.h1}) {
      const double t = (h - p.y) / d.y;
      const double w = t * (a * t + 2.0 * b) + c;   // squared distance from the axis where the ray meets the plane
      if (w >= inner2 && w <= outer2) add(t);
    }
  }
  for (const double r2 : {inner2, outer2}) {
    if (!(r2 > tolerance::epsilon)) continue;
    double disc = b * b - a * (c - r2);
    if (!(disc > 0.0)) continue;
    disc = std::sqrt(disc);
    for (const double t : {(-b + disc) / a, (-b - disc) / a}) {
      const double h = p.y + t * d.y;
      if (h >= ring.h1 && h <= ring.h2) add(t);
    }
  }
  if (count == 0) return false;
  if (count == 2 || count == 4) return farthest > tolerance::epsilon;
  return true;
}

}  // namespace povtrace::render

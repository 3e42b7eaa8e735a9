// The shapes swept from a 2-D profile: lathe, prism, sor (surface of revolution), as the parser leaves them. The
// profile points are kept as written (shared by copies of the object); the renderer turns each run of points into
// POV-Ray's per-segment cubic polynomials.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

namespace povtrace {

enum class SplineKind { linear, quadratic, cubic, bezier };
using ProfilePoint = std::array<double, 2>;
using Profile = std::shared_ptr<const std::vector<ProfilePoint>>;

// lathe { [linear_spline | quadratic_spline | cubic_spline | bezier_spline] N, <x, y>… [sturm] }: the profile in
// the x-y plane (x the radius, y the height) turned about the y axis. Segment k uses points k… (linear: k, k+1;
// quadratic: k…k+2; cubic: k…k+3), a Bézier segment k the four points 4k…4k+3.
struct Lathe {
  SplineKind spline = SplineKind::linear;
  Profile points;
  bool sturm = false;
};

// prism { [spline] [linear_sweep | conic_sweep] H1, H2, N, <x, z>… [open] [sturm] }: the 2-D outline (points as
// written, plus the closing point POV-Ray appends to an unclosed linear outline) swept along y from H1 to H2
// (sorted), straight up or (conic_sweep) as a cone from the origin. `segment_starts` holds the first point of each
// spline segment in POV-Ray's order (Compute_Prism steps over the gap between one closed sub-outline and the next).
// A non-linear outline that does not close is `degenerate`: POV-Ray warns and never hits it.
struct Prism {
  SplineKind spline = SplineKind::linear;
  bool conic = false;
  double height1 = 0, height2 = 1;
  Profile points;
  std::shared_ptr<const std::vector<std::uint32_t>> segment_starts;
  bool open = false;
  bool sturm = false;
  bool degenerate = false;
};

// sor { N, <r, y>… [open] [sturm] }: radius r as a cubic function of the height y between consecutive points, the
// first and last points only setting the slopes at the ends (N − 3 segments); closed by discs unless `open`.
struct Sor {
  Profile points;
  bool open = false;
  bool sturm = false;
};

// POV-Ray's Compute_Prism walk over the points: the first point of each segment, or nothing when a segment would
// need points past the end (POV-Ray's error "Too few points in prism").
std::optional<std::vector<std::uint32_t>> prism_segment_starts(SplineKind spline,
                                                               const std::vector<ProfilePoint>& points);

}  // namespace povtrace

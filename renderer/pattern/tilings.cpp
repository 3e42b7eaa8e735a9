// checker, hexagon and brick: patterns with a value per cell (0, 1 or 2) that pick entries of a list.
#include <cmath>
#include <limits>

#include "renderer/pattern/pattern_functions.hpp"

namespace povtrace::render::patterns {

namespace {
// POV-Ray's EPSILON, which both checker and brick add to the point.
constexpr double kPovEpsilon = 1e-10;

// The fractional part as POV-Ray's brick computes it: v minus its integer part (truncated toward zero), moved
// into [0, 1) when negative.
double wrapped_fraction(double v) {
  const double f = v - std::trunc(v);
  return f < 0.0 ? f + 1.0 : f;
}

// hexagon's cell size in x and z: POV-Ray works in units of half a hexagon side along x and of the hexagon's
// inradius (√3/2, written 0.866025404) along z.
constexpr double kHexHalfSide = 0.5;
constexpr double kHexInradius = 0.866025404;
}  // namespace

// Parity of floor(x+ε)+floor(y+ε)+floor(z+ε): even 0, odd 1 ([V sdl_checker]).
double checker(Vec3 p) {
  const auto sum = static_cast<long long>(std::floor(p.x + kPovEpsilon)) +
                   static_cast<long long>(std::floor(p.y + kPovEpsilon)) +
                   static_cast<long long>(std::floor(p.z + kPovEpsilon));
  return static_cast<double>(sum & 1);
}

// Regular hexagons in the x-z plane, circumradius 1, one centred on the origin with corners on the x axis: the
// centres are (1.5·i, 0.866·j) with i + j even, so each point takes the nearest centre. Along a column the three
// colours repeat every 3 hexagons, and odd columns are shifted by one and a half of them: colour (j + 3·|i mod 2|)/2
// mod 3 (POV-Ray's hexagon_pattern, which gets the same tiling from a 6×6 grid of half-cells).
double hexagon(Vec3 p) {
  const double u = p.x / kHexHalfSide;   // centres at u = 3i
  const double w = p.z / kHexInradius;   // centres at w = j
  const auto i0 = static_cast<long long>(std::floor(u / 3.0));
  const auto j0 = static_cast<long long>(std::floor(w));
  double best = std::numeric_limits<double>::infinity();
  long long best_i = 0, best_j = 0;
  for (long long i = i0; i <= i0 + 1; ++i)
    for (long long j = j0 - 1; j <= j0 + 2; ++j) {
      if (((i + j) & 1) != 0) continue;
      const double dx = (u - 3.0 * static_cast<double>(i)) * kHexHalfSide;
      const double dz = (w - static_cast<double>(j)) * kHexInradius;
      const double d2 = dx * dx + dz * dz;
      if (d2 < best) { best = d2; best_i = i; best_j = j; }
    }
  const long long shifted = best_j + 3 * (best_i & 1);   // even by construction
  const long long colour = ((shifted / 2) % 3 + 3) % 3;
  return static_cast<double>(colour);
}

// Bricks of `size` laid in courses along y, mortar joints of width `mortar` at the low side of each brick. Courses
// alternate: the first of each pair has its end joints (across x) at whole brick widths and its facing joints
// (across z) at half depths, the second the other way round (POV-Ray's brick_pattern). 0 is mortar, 1 brick.
double brick(Vec3 p, Vec3 size, double mortar) {
  const double shift = kPovEpsilon + mortar;
  const Vec3 q{p.x + shift, p.y + shift, p.z + shift};
  if (wrapped_fraction(q.y / size.y) <= mortar / size.y) return 0.0;
  const bool first_course = wrapped_fraction((q.y / size.y) * 0.5) <= 0.5;
  const double end_offset = first_course ? 0.0 : 0.5;
  const double face_offset = first_course ? 0.5 : 0.0;
  if (wrapped_fraction(q.x / size.x + end_offset) <= mortar / size.x) return 0.0;
  if (wrapped_fraction(q.z / size.z + face_offset) <= mortar / size.z) return 0.0;
  return 1.0;
}

}  // namespace povtrace::render::patterns

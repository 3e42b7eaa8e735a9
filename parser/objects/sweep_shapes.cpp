// lathe, prism and sor (povray-sdl-and-geometry.md §8). Facts from POV-Ray 3.7's parser (source/backend/parser/
// parse.cpp Parse_Lathe, Parse_Prism, Parse_Sor; shape/prism.cpp Compute_Prism; shape/sor.cpp Compute_Sor,
// 3.7-stable):
// - The body may be a declared object instead (Parse_Object_Id). The spline keywords (and the prism's sweep
//   keywords) come first, in any order, the last one of a kind winning; linear_spline and linear_sweep are the
//   defaults. The point count is truncated to an integer; commas before points are optional; points are UV vectors.
// - lathe: at least 2 (linear), 3 (quadratic) or 4 (cubic) points, Bézier a multiple of four (zero too: an empty
//   lathe); a point other than the first and the last with x < 0 is an error.
// - prism: H1, H2 (swapped when H1 > H2), at least 3/5/6 points (linear/quadratic/cubic), Bézier a multiple of four;
//   then `open` may follow the points directly. An outline is closed where a point repeats the first point of its
//   sub-outline (within 1e-10 per coordinate); an unclosed linear outline is closed with a warning, any other is
//   ignored with a warning ("Prism not closed. Ignoring it."), and a quadratic or cubic one whose segments would
//   then need points past the end is the error "Too few points in prism".
// - sor: at least 4 points; x < 0 anywhere, or a height not above the previous one (points 2 … N−2), is "Incorrect
//   point in surface of revolution", and so are two heights two points apart closer than 1e-10 (Compute_Sor). Then
//   `open` may follow.
// - `sturm` is an object modifier on all three (try_sturm_modifier).
#include <cmath>

#include "parser/expressions/int_cast.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON

bool same_point(const ProfilePoint& a, const ProfilePoint& b) {
  return std::fabs(a[0] - b[0]) < kEpsilon && std::fabs(a[1] - b[1]) < kEpsilon;
}
bool different_point(const ProfilePoint& a, const ProfilePoint& b) {   // not quite !same_point, as in POV-Ray
  return std::fabs(a[0] - b[0]) > kEpsilon || std::fabs(a[1] - b[1]) > kEpsilon;
}
// Points from a segment's first point to its end point, and from a closing point to the next sub-outline's start.
int segment_end_offset(SplineKind s) { return s == SplineKind::linear ? 1 : 2; }
int closing_skip(SplineKind s) { return s == SplineKind::linear ? 1 : s == SplineKind::quadratic ? 2 : 3; }
int window_size(SplineKind s) { return s == SplineKind::linear ? 2 : s == SplineKind::quadratic ? 3 : 4; }
}  // namespace

std::optional<std::vector<std::uint32_t>> prism_segment_starts(SplineKind spline,
                                                               const std::vector<ProfilePoint>& points) {
  const long n = static_cast<long>(points.size());
  std::vector<std::uint32_t> starts;
  ProfilePoint first = points.empty() ? ProfilePoint{} : points[spline == SplineKind::linear ? 0 : 1];
  for (long i = 0; i < n - 1; ++i) {
    if (i + window_size(spline) > n) return std::nullopt;
    starts.push_back(static_cast<std::uint32_t>(i));
    if (spline == SplineKind::bezier) {
      i += 3;
      continue;
    }
    if (same_point(points[i + segment_end_offset(spline)], first)) {
      i += closing_skip(spline);
      if (i + segment_end_offset(spline) < n) first = points[i + segment_end_offset(spline)];
    }
  }
  return starts;
}

namespace sdl {

namespace {
const char* spline_name(SplineKind s) {
  switch (s) {
    case SplineKind::linear: return "linear";
    case SplineKind::quadratic: return "quadratic";
    case SplineKind::cubic: return "cubic";
    case SplineKind::bezier: return "Bezier";
  }
  return "";
}

// Parse_Prism's closing test for linear, quadratic and cubic outlines: the last sub-outline must end on its first
// point (the loop's last comparison decides).
bool spline_outline_closed(SplineKind spline, const std::vector<ProfilePoint>& p, ProfilePoint& start) {
  const std::size_t first = spline == SplineKind::linear ? 0 : 1;
  start = p[first];
  bool closed = false;
  for (std::size_t i = first + 1; i < p.size(); ++i) {
    closed = false;
    if (same_point(start, p[i])) {
      i += static_cast<std::size_t>(closing_skip(spline));
      if (i < p.size()) start = p[i];
      closed = true;
    }
  }
  return closed;
}

// Bézier outlines: every run of segments joined end to start must come back to where it began.
bool bezier_outline_closed(const std::vector<ProfilePoint>& p) {
  if (p.empty()) return true;
  std::size_t loop_start = 0;
  for (std::size_t i = 4; i < p.size(); i += 4) {
    if (!different_point(p[i], p[i - 1])) continue;
    if (different_point(p[i - 1], p[loop_start])) return false;
    loop_start = i;
  }
  return !different_point(p.back(), p[loop_start]);
}
}  // namespace

// The spline keywords (and with `sweeps`, the prism's sweep keywords), in any order.
SplineKind ObjectParser::parse_spline_keywords(bool* conic) {
  SplineKind spline = SplineKind::linear;
  while (true) {
    const Token t = next();
    if (t.is("linear_spline")) spline = SplineKind::linear;
    else if (t.is("quadratic_spline")) spline = SplineKind::quadratic;
    else if (t.is("cubic_spline")) spline = SplineKind::cubic;
    else if (t.is("bezier_spline")) spline = SplineKind::bezier;
    else if (conic && t.is("linear_sweep")) *conic = false;
    else if (conic && t.is("conic_sweep")) *conic = true;
    else {
      unget(t);
      return spline;
    }
  }
}

// The point count (truncated) and its POV-Ray minimum for the spline kind; Bézier counts must be multiples of four.
long ObjectParser::parse_profile_count(const std::string& shape, SplineKind spline, const long minimum[3]) {
  const Token at = peek();
  const long count = saturating_cast<int>(parse_float());
  const long least = spline == SplineKind::bezier ? 0 : minimum[static_cast<int>(spline)];
  if (spline != SplineKind::bezier && count < least)
    fail_at(at, shape + " with " + spline_name(spline) + " splines must have at least " + std::to_string(least) +
                    " points (POV-Ray refuses it too)");
  if (spline == SplineKind::bezier && (count < 0 || count % 4 != 0))
    fail_at(at, shape + " with Bezier splines must have four points per segment (a multiple of four)");
  return count;
}

// N points, each an optional comma and a UV vector; `check(i, point, at)` may refuse one.
std::vector<ProfilePoint> ObjectParser::parse_profile_points(
    long count, const std::function<void(long, const std::vector<ProfilePoint>&, const Token&)>& check) {
  std::vector<ProfilePoint> points;
  for (long i = 0; i < count; ++i) {
    accept(",");
    const Token at = peek();
    const auto [x, y] = parse_uv_vector("as a profile point");
    points.push_back({x, y});
    check(i, points, at);
  }
  return points;
}

Object ObjectParser::parse_lathe(const Token& keyword) {
  expect("{", " after 'lathe'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  Lathe l;
  l.spline = parse_spline_keywords(nullptr);
  static const long minimum[3] = {2, 3, 4};
  const long count = parse_profile_count("a lathe", l.spline, minimum);
  l.points = std::make_shared<const std::vector<ProfilePoint>>(
      parse_profile_points(count, [&](long i, const std::vector<ProfilePoint>& p, const Token& at) {
        if (i > 0 && i < count - 1 && p.back()[0] < 0.0)
          fail_at(at, "incorrect point in lathe: only the first and the last point may have x < 0");
      }));
  o.shape = l;
  parse_object_modifiers(o);
  return o;
}

// Parse_Prism's closing rules (see the top of this file) applied to the points read.
void ObjectParser::close_prism_outline(const Token& keyword, Prism& prism, std::vector<ProfilePoint>& points) {
  ProfilePoint start{};
  const bool closed = prism.spline == SplineKind::bezier ? bezier_outline_closed(points)
                                                         : spline_outline_closed(prism.spline, points, start);
  if (!closed && prism.spline == SplineKind::linear) {
    points.push_back(start);
    warn(keyword.loc, "linear prism not closed; closing it (as POV-Ray does)");
  } else if (!closed) {
    prism.degenerate = true;
    warn(keyword.loc, "prism not closed; POV-Ray ignores it, and so does povtrace");
  }
  auto starts = prism_segment_starts(prism.spline, points);
  if (!starts)
    fail_at(keyword, "too few points in prism: a sub-outline does not close or control points are missing "
                     "(POV-Ray refuses it too)");
  prism.segment_starts = std::make_shared<const std::vector<std::uint32_t>>(std::move(*starts));
}

Object ObjectParser::parse_prism(const Token& keyword) {
  expect("{", " after 'prism'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  Prism p;
  p.spline = parse_spline_keywords(&p.conic);
  p.height1 = parse_float();
  accept(",");
  p.height2 = parse_float();
  accept(",");
  if (p.height1 > p.height2) std::swap(p.height1, p.height2);
  static const long minimum[3] = {3, 5, 6};
  const long count = parse_profile_count("a prism", p.spline, minimum);
  auto points = parse_profile_points(count, [](long, const std::vector<ProfilePoint>&, const Token&) {});
  p.open = accept_open();
  close_prism_outline(keyword, p, points);
  p.points = std::make_shared<const std::vector<ProfilePoint>>(std::move(points));
  o.shape = p;
  parse_object_modifiers(o);
  return o;
}

Object ObjectParser::parse_sor(const Token& keyword) {
  expect("{", " after 'sor'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);
  Object o;
  o.loc = keyword.loc;
  Sor s;
  const Token count_at = peek();
  const long count = saturating_cast<int>(parse_float());
  if (count < 4) fail_at(count_at, "a surface of revolution must have at least four points (POV-Ray refuses it too)");
  std::vector<SourceLoc> at;
  auto points = parse_profile_points(count, [&](long i, const std::vector<ProfilePoint>& p, const Token& t) {
    at.push_back(t.loc);
    if (p.back()[0] < 0.0 || (i > 1 && i < count - 1 && p.back()[1] <= p[p.size() - 2][1]))
      fail_at(t, "incorrect point in surface of revolution: x must not be negative and the heights of points 2 "
                 "to N-1 must increase");
  });
  for (std::size_t i = 0; i + 3 < points.size(); ++i)   // Compute_Sor: each segment's slopes need two heights
    for (std::size_t k : {i + 2, i + 3})
      if (std::fabs(points[k][1] - points[k - 2][1]) < kEpsilon)
        fail(at[k], "incorrect point in surface of revolution: its height equals that of the point two before");
  s.open = accept_open();
  s.points = std::make_shared<const std::vector<ProfilePoint>>(std::move(points));
  o.shape = s;
  parse_object_modifiers(o);
  return o;
}

}  // namespace sdl
}  // namespace povtrace

// rainbow { … } at the top level of a scene. Facts from POV-Ray 3.7's Parse_Rainbow (source/backend/parser/
// parstxtr.cpp) and Create_Rainbow (scene/atmosph.cpp), 3.7-stable:
// - items in any order: angle, direction, colour_map (read through a gradient x pattern), distance, jitter, width,
//   up, falloff_angle, arc_angle; defaults distance MAX_DISTANCE, angle/width/jitter 0, direction <0, 0, 0>, up y,
//   arc and falloff angle 180 (in those units, never converted when not written).
// - falloff_angle and arc_angle must be 0…360 and are stored halved in radians (· π/360); arc_angle alone sets the
//   falloff angle too; an arc angle below the falloff angle is an error; falloff width = arc − falloff.
// - direction and up must not be zero nor co-linear; they are normalised, right = up × direction, up = direction
//   × right, both normalised again.
// - angle −= width / 2, then angle and width into radians.
#include <cmath>

#include "parser/interpreter.hpp"
#include "parser/textures/texture_parser.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON
constexpr double kHalfDegree = M_PI / 360.0;   // POV-Ray's M_PI_360
constexpr double kDegree = M_PI / 180.0;       // M_PI_180

Vec3 unit(Vec3 v) { return v * (1.0 / std::sqrt(dot(v, v))); }
}  // namespace

Rainbow TextureParser::parse_rainbow(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'rainbow'");
  Rainbow r;
  r.loc = keyword.loc;
  bool falloff_given = false, arc_given = false;
  Token arc_at = keyword;
  auto half_angle = [this](const Token& t, const char* what) {
    const double a = parse_float();
    if (a < 0.0 || a > 360.0) fail_at(t, std::string("the rainbow's ") + what + " must be 0 to 360 degrees");
    return a * kHalfDegree;
  };
  for (Token t = next(); !t.is("}"); t = next()) {
    if (t.is("angle")) {
      r.angle = parse_float();
    } else if (t.is("direction")) {
      r.antisolar = parse_vector();
    } else if (t.is("colour_map") || t.is("color_map")) {
      Pigment p = default_pigment();
      p.pattern = PatternKind::gradient;
      p.gradient = Vec3{1, 0, 0};
      p.entries = parse_blend_map(t).entries;
      p.loc = t.loc;
      r.colour_map = std::move(p);
    } else if (t.is("distance")) {
      r.distance = parse_float();
    } else if (t.is("jitter")) {
      r.jitter = parse_float();
    } else if (t.is("width")) {
      r.width = parse_float();
    } else if (t.is("up")) {
      r.up = parse_vector();
    } else if (t.is("falloff_angle")) {
      falloff_given = true;
      r.falloff_angle = half_angle(t, "falloff_angle");
    } else if (t.is("arc_angle")) {
      arc_given = true;
      arc_at = t;
      r.arc_angle = half_angle(t, "arc_angle");
    } else {
      fail_expected(t, "a rainbow item (angle, width, distance, direction, up, jitter, arc_angle, falloff_angle, "
                       "colour_map) or '}'");
    }
  }
  if (arc_given && !falloff_given) r.falloff_angle = r.arc_angle;
  if (r.arc_angle < r.falloff_angle) fail_at(arc_given ? arc_at : keyword, "the rainbow's arc_angle is smaller than its falloff_angle");
  r.falloff_width = r.arc_angle - r.falloff_angle;
  if (std::fabs(dot(r.antisolar, r.antisolar)) < kEpsilon) fail_at(keyword, "the rainbow's direction vector is zero (give it a direction)");
  if (std::fabs(dot(r.up, r.up)) < kEpsilon) fail_at(keyword, "the rainbow's up vector is zero");
  r.antisolar = unit(r.antisolar);
  r.up = unit(r.up);
  if (std::fabs(1.0 - std::fabs(dot(r.up, r.antisolar))) < kEpsilon)
    fail_at(keyword, "the rainbow's up and direction vectors are co-linear");
  r.right = cross(r.up, r.antisolar);
  r.up = unit(cross(r.antisolar, r.right));
  r.right = unit(r.right);
  r.angle -= 0.5 * r.width;
  r.angle *= kDegree;
  r.width *= kDegree;
  return r;
}

}  // namespace povtrace::sdl

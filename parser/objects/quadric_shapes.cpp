// cylinder, cone, disc and torus (povray-sdl-and-geometry.md §8). Facts from POV-Ray 3.7's parser
// (source/backend/parser/parse.cpp, Parse_Cylinder/Parse_Cone/Parse_Disc/Parse_Torus, 3.7-stable):
// - Commas between parameters are optional (Parse_Comma), including the one after a disc's outer radius.
// - `open` is read only right after a cylinder's or cone's parameters, before the object modifiers; anywhere else
//   it is not a modifier (see try_object_modifier).
// - A cylinder or cone whose end points are closer than EPSILON (1e-10) is an error ("Degenerate cone/cylinder");
//   equal cone radii (|r1 − r2| < EPSILON) make it a cylinder — the renderer does that part.
// - The disc normal is normalised as written; a zero normal gives POV-Ray NaNs and the disc renders nothing, which
//   povtrace says with a warning and reproduces by not rendering it. The hole radius is optional.
// - torus takes the major and the minor radius; `sturm` is an object modifier (try_object_modifier).
#include <cmath>

#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON

// Words that start an object modifier, so cannot start the optional hole radius of a disc.
bool is_object_modifier_word(std::string_view w) {
  static const std::string_view words[] = {
      "translate", "rotate", "scale", "matrix", "transform", "texture", "pigment", "finish", "normal", "interior",
      "material", "no_shadow", "inverse", "hollow", "sturm", "open", "clipped_by", "bounded_by", "no_image",
      "no_reflection", "no_radiosity", "double_illuminate", "interior_texture", "uv_mapping", "photons",
      "radiosity", "split_union", "cutaway_textures", "uv_vectors", "texture_list"};
  for (auto m : words)
    if (w == m) return true;
  return false;
}
}  // namespace

// `open` directly after the parameters of a cylinder or cone.
bool ObjectParser::accept_open() {
  Token t = next();
  if (t.is("open")) return true;
  unget(t);
  return false;
}

void ObjectParser::check_cone_axis(const Token& keyword, Vec3 end1, Vec3 end2) {
  if (length(end1 - end2) < kEpsilon)
    fail_at(keyword, "degenerate " + std::string(keyword.text) + ": its two end points are the same point (" +
                         "POV-Ray refuses it too)");
}

Object ObjectParser::parse_cylinder(const Token& keyword) {
  expect("{", " after 'cylinder'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Cylinder c;
  c.end1 = parse_vector();
  accept(",");
  c.end2 = parse_vector();
  accept(",");
  c.radius = parse_float();
  c.open = accept_open();
  check_cone_axis(keyword, c.end1, c.end2);
  o.shape = c;
  parse_object_modifiers(o);
  return o;
}

Object ObjectParser::parse_cone(const Token& keyword) {
  expect("{", " after 'cone'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Cone c;
  c.end1 = parse_vector();
  accept(",");
  c.radius1 = parse_float();
  accept(",");
  c.end2 = parse_vector();
  accept(",");
  c.radius2 = parse_float();
  c.open = accept_open();
  check_cone_axis(keyword, c.end1, c.end2);
  o.shape = c;
  parse_object_modifiers(o);
  return o;
}

Object ObjectParser::parse_disc(const Token& keyword) {
  expect("{", " after 'disc'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Disc d;
  d.centre = parse_vector();
  accept(",");
  const Token normal_at = peek();
  const Vec3 n = parse_vector();
  accept(",");
  if (length(n) == 0) {
    warn(normal_at.loc, "the disc's normal is the zero vector; POV-Ray renders nothing for it");
    d.normal = Vec3{};
  } else {
    d.normal = normalize(n);
  }
  d.radius = parse_float();
  accept(",");
  // An optional hole radius: POV-Ray reads a float when the next token can start one.
  const Token next_token = peek();
  if (!next_token.is("}") && next_token.kind != TokenKind::end_of_input &&
      !(next_token.kind == TokenKind::identifier && is_object_modifier_word(next_token.text)))
    d.hole_radius = parse_float();
  o.shape = d;
  parse_object_modifiers(o);
  return o;
}

Object ObjectParser::parse_torus(const Token& keyword) {
  expect("{", " after 'torus'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Torus t;
  t.major = parse_float();
  accept(",");
  t.minor = parse_float();
  o.shape = t;
  parse_object_modifiers(o);
  return o;
}

// POV-Ray: `sturm` on an object whose type is not STURM_OK_OBJECT is the error "Keyword 'sturm' cannot be used with
// this object"; an optional float follows, and sturm is on when it is > 0. CSG is never STURM_OK. A shape povtrace
// skips unrendered (lathe, sor, prism, blob… which may take sturm) is left to the caller, which refuses it by name.
bool ObjectParser::try_sturm_modifier(const Token& t, Object& object) {
  if (!std::holds_alternative<Csg>(object.shape) && object.unsupported) return false;
  bool* flag = nullptr;
  if (auto* torus = std::get_if<Torus>(&object.shape)) flag = &torus->sturm;
  if (auto* blob = std::get_if<Blob>(&object.shape)) flag = &blob->sturm;
  if (auto* poly = std::get_if<Poly>(&object.shape)) flag = &poly->sturm;
  if (auto* lathe = std::get_if<Lathe>(&object.shape)) flag = &lathe->sturm;
  if (auto* prism = std::get_if<Prism>(&object.shape)) flag = &prism->sturm;
  if (auto* sor = std::get_if<Sor>(&object.shape)) flag = &sor->sturm;
  if (auto* ovus = std::get_if<Ovus>(&object.shape)) flag = &ovus->sturm;
  if (!flag) fail_at(t, "keyword 'sturm' cannot be used with this object (POV-Ray takes it only on shapes "
                        "solved as polynomials: torus, blob, lathe, sor, prism, ovus, poly)");
  bool on = true;
  const Token n = peek();
  if (n.kind == TokenKind::number || n.is("on") || n.is("off") || n.is("true") || n.is("false") || n.is("yes") ||
      n.is("no") || n.is("(") || n.is("-") || n.is("+") || n.is("!"))
    on = parse_float() > 0.0;
  *flag = on;
  return true;
}

}  // namespace povtrace::sdl

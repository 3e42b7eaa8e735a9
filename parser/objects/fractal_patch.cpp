// julia_fractal and bicubic_patch. Facts from POV-Ray 3.7's parser and shapes (source/backend/parser/parse.cpp
// Parse_Julia_Fractal, Parse_Bicubic_Patch; shape/fractal.cpp SetUp_Fractal, Compute_BBox; shape/bezier.cpp, 3.7-stable):
// - julia_fractal { <c> items… modifiers }: c is a 4-D vector (a float fills all four components, a shorter vector
//   is padded with zeros); then in any order, the last one winning: quaternion | hypercomplex, a function (sqr, cube,
//   reciprocal, exp, ln, sin, asin, cos, acos, tan, atan, sinh, asinh, cosh, acosh, tanh, atanh, pwr(x, y)),
//   max_iteration N (floored, at least 1), precision P (at least 1; the march step is 1/P) and slice <S> [,] D (S
//   normalised; a zero S or S.t is an error). Quaternions take only sqr and cube. SetUp_Fractal runs after the
//   modifiers and clears the fractal's inversion, which every later transform clears again (transform_object).
// - bicubic_patch { items… [,] P1 [,] … P16 modifiers }: type (mandatory: POV-Ray's default −1 is an error; above 1
//   is 1 with a warning), flatness, u_steps, v_steps, accuracy (no effect), uv_vectors (four, and the last item);
//   a float where an item is expected starts POV-Ray's old syntax "type [flatness] u_steps v_steps" (flatness only
//   for types 2 and 3, else 0.1). The points may be separated by commas, with none after the last.
#include <cmath>
#include <limits>

#include "parser/expressions/int_cast.hpp"
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kEpsilon = 1e-10;   // POV-Ray's EPSILON
// Beyond these POV-Ray runs for hours or exhausts memory; povtrace refuses them by name instead.
constexpr int kMaxJuliaIterations = 100000;
constexpr double kMaxJuliaPrecision = 1e6;
constexpr int kMaxPatchSteps = 20;   // u_steps + v_steps: up to 2^20 pieces per patch

struct JuliaFunctionWord {
  std::string_view word;
  JuliaFunction function;
};
constexpr JuliaFunctionWord kJuliaFunctions[] = {
    {"sqr", JuliaFunction::sqr},     {"cube", JuliaFunction::cube},   {"reciprocal", JuliaFunction::reciprocal},
    {"exp", JuliaFunction::exp},     {"ln", JuliaFunction::ln},       {"sin", JuliaFunction::sin},
    {"asin", JuliaFunction::asin},   {"cos", JuliaFunction::cos},     {"acos", JuliaFunction::acos},
    {"tan", JuliaFunction::tan},     {"atan", JuliaFunction::atan},   {"sinh", JuliaFunction::sinh},
    {"asinh", JuliaFunction::asinh}, {"cosh", JuliaFunction::cosh},   {"acosh", JuliaFunction::acosh},
    {"tanh", JuliaFunction::tanh},   {"atanh", JuliaFunction::atanh}, {"pwr", JuliaFunction::pwr}};
}  // namespace

// Parse_Vector4D: a float stands for all four components; a shorter vector is padded with zeros.
std::array<double, 4> ObjectParser::parse_vector4(std::string_view what) {
  const Token at = peek();
  const Numeric n = parse_additive();
  if (n.terms > 4) fail_at(at, "expected a 4-D vector (" + std::string(what) + "), found a colour");
  if (n.terms == 1) return {n.v[0], n.v[0], n.v[0], n.v[0]};
  std::array<double, 4> v{0, 0, 0, 0};
  for (int k = 0; k < n.terms; ++k) v[static_cast<std::size_t>(k)] = n.v[static_cast<std::size_t>(k)];
  return v;
}

void ObjectParser::parse_julia_slice(JuliaFractal& j) {
  const Token at = peek();
  const std::array<double, 4> s = parse_vector4("the slice vector");
  accept(",");
  j.slice_distance = parse_float();
  const double p = s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + s[3] * s[3];
  if (std::fabs(p) < kEpsilon) fail_at(at, "the slice vector is zero (POV-Ray: \"Slice vector is zero.\")");
  if (std::fabs(s[3]) < kEpsilon)
    fail_at(at, "the slice vector's 4th component is zero (POV-Ray: \"Slice t component is zero.\")");
  const double inverse_length = 1.0 / std::sqrt(p);
  for (std::size_t k = 0; k < 4; ++k) j.slice[k] = s[k] * inverse_length;
}

bool ObjectParser::is_julia_item(const Token& t) {
  if (t.kind != TokenKind::identifier) return false;
  static const std::string_view words[] = {"quaternion", "hypercomplex", "max_iteration", "precision", "slice"};
  for (auto w : words)
    if (t.is(w)) return true;
  for (const auto& f : kJuliaFunctions)
    if (t.is(f.word)) return true;
  return false;
}

// The julia_fractal item `t` (already read): its arguments.
void ObjectParser::parse_julia_item(const Token& t, JuliaFractal& j, std::optional<Token>& function_at) {
  if (t.is("quaternion")) { j.algebra = JuliaAlgebra::quaternion; return; }
  if (t.is("hypercomplex")) { j.algebra = JuliaAlgebra::hypercomplex; return; }
  if (t.is("max_iteration")) {
    const Token at = peek();
    const double n = std::floor(parse_float());
    if (n > kMaxJuliaIterations)
      fail_at(at, "max_iteration above " + std::to_string(kMaxJuliaIterations) + " is not rendered");
    j.max_iteration = std::max(1, saturating_cast<int>(n));
    return;
  }
  if (t.is("precision")) {
    const Token at = peek();
    const double p = std::max(1.0, parse_float());
    if (!(p <= kMaxJuliaPrecision)) fail_at(at, "a julia_fractal precision above 1e6 is not rendered");
    j.precision = 1.0 / p;
    return;
  }
  if (t.is("slice")) { parse_julia_slice(j); return; }
  for (const auto& [word, function] : kJuliaFunctions)
    if (t.is(word)) {
      j.function = function;
      function_at = t;
      if (function == JuliaFunction::pwr) {
        expect("(", " after 'pwr' (pwr(X, Y) in a julia_fractal)");
        j.exponent[0] = parse_float();
        accept(",");
        j.exponent[1] = parse_float();
        expect(")", " closing pwr(X, Y)");
      }
      return;
    }
}

Object ObjectParser::parse_julia_fractal(const Token& keyword) {
  expect("{", " after 'julia_fractal'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  JuliaFractal j;
  j.julia = parse_vector4("the julia parameter");
  std::optional<Token> function_at;
  while (true) {
    const Token t = peek();
    if (!is_julia_item(t)) {
      if (t.kind == TokenKind::identifier && ExpressionParser::is_float_function(t.text))
        fail_expected(t, "a julia_fractal item (quaternion, hypercomplex, a fractal function, max_iteration, "
                         "precision, slice) or an object modifier");
      break;
    }
    next();
    parse_julia_item(t, j, function_at);
  }
  if (j.algebra == JuliaAlgebra::quaternion && j.function != JuliaFunction::sqr && j.function != JuliaFunction::cube)
    fail_at(*function_at, "a quaternion julia_fractal supports only sqr and cube (POV-Ray: \"Illegal function: "
                          "quaternion only supports sqr and cube\")");
  o.shape = j;
  parse_object_modifiers(o);
  o.inverse = false;   // SetUp_Fractal's Compute_BBox clears the inversion: `inverse` in the block has no effect
  return o;
}

// The patch items before the points (see the top of this file); the old positional syntax ends them.
void ObjectParser::parse_patch_items(BicubicPatch& b) {
  while (true) {
    const Token t = peek();
    if (t.is("type")) { next(); b.type = saturating_cast<int>(parse_float()); continue; }
    if (t.is("flatness")) { next(); b.flatness = parse_float(); continue; }
    if (t.is("u_steps")) { next(); b.u_steps = saturating_cast<int>(parse_float()); continue; }
    if (t.is("v_steps")) { next(); b.v_steps = saturating_cast<int>(parse_float()); continue; }
    if (t.is("accuracy")) { next(); (void)parse_float(); continue; }   // kept by POV-Ray, used nowhere
    if (t.is("uv_vectors")) {   // ends the items (Parse_Bicubic_Patch leaves its loop after it)
      next();
      for (std::size_t k = 0; k < 4; ++k) {
        const auto [u, v] = parse_uv_vector("(a uv_vectors corner)");
        b.uv_vectors[k] = {u, v};
        if (k < 3) accept(",");
      }
      return;
    }
    const double old_type = optional_float(std::numeric_limits<double>::quiet_NaN());
    if (std::isnan(old_type)) return;   // no float: the points follow
    warn(t.loc, "bicubic_patch: should use keywords for the patch parameters (POV-Ray's old syntax "
                "\"type [flatness] u_steps v_steps\")");
    b.type = saturating_cast<int>(old_type);
    b.flatness = (b.type == 2 || b.type == 3) ? parse_float() : 0.1;
    b.u_steps = saturating_cast<int>(parse_float());
    b.v_steps = saturating_cast<int>(parse_float());
    return;
  }
}

Object ObjectParser::parse_bicubic_patch(const Token& keyword) {
  expect("{", " after 'bicubic_patch'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  BicubicPatch b;
  b.type = -1;   // POV-Ray's default, which is an error: `type` must be given
  const Token items_at = peek();
  parse_patch_items(b);
  if (b.type > 1) {
    warn(items_at.loc, "bicubic_patch type " + std::to_string(b.type) + " is no longer supported; using type 1 "
                       "(as POV-Ray 3.7)");
    b.type = 1;
  }
  if (b.type < 0) fail_at(items_at, "bicubic_patch needs 'type 0' or 'type 1' before its points (POV-Ray: "
                                    "\"Undefined bicubic patch type.\")");
  if (std::max(b.u_steps, 0) + std::max(b.v_steps, 0) > kMaxPatchSteps)
    fail_at(items_at, "bicubic_patch u_steps + v_steps above " + std::to_string(kMaxPatchSteps) +
                          " (2^" + std::to_string(kMaxPatchSteps) + " pieces) is not rendered");
  accept(",");
  for (std::size_t k = 0; k < 16; ++k) {
    b.points[k] = parse_vector();
    if (k < 15) accept(",");
  }
  o.shape = b;
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl

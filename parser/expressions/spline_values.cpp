// SDL spline values (POV-Ray 3.7: Parse_Spline and Parse_Spline_Call in express.cpp, read for their behaviour):
//   spline { [S] [linear_spline | quadratic_spline | cubic_spline | natural_spline]… T1, V1 [,] T2, V2 [,] … }
// - An optional spline identifier S first: the new spline starts as a copy of it (its entries, type and size),
//   and what follows changes the type or adds entries.
// - Type keywords only before the entries, any number of them, the last one winning (linear by default). A type
//   keyword after an entry is an error (POV-Ray: "No matching }").
// - Each entry is a float T, an optional comma, a float or vector V (1 to 5 components, no colour keyword:
//   POV-Ray parses V as a plain expression) and an optional comma. A float V stands for <V, V>. The entries are
//   kept sorted by T whatever their order; a repeated T replaces the earlier value (splines.hpp has the one
//   exception). At least one entry is required, counting a copied spline's.
// - A call S(t) or S(t, type) returns as many components as the largest V given, at least 2 (a float V counts
//   as 2); `type` evaluates a copy interpolated that way.
#include <algorithm>

#include "parser/expressions/spline_values.hpp"
#include "parser/interpreter.hpp"

namespace povtrace::sdl {

namespace {
std::optional<SplineType> spline_type_keyword(const Token& t) {
  if (t.kind != TokenKind::identifier) return std::nullopt;
  if (t.text == "linear_spline") return SplineType::linear;
  if (t.text == "quadratic_spline") return SplineType::quadratic;
  if (t.text == "cubic_spline") return SplineType::cubic;
  if (t.text == "natural_spline") return SplineType::natural;
  return std::nullopt;
}

const SplineValue* spline_of(const Value* v) {
  const auto* s = v ? std::get_if<Boxed<SplineValue>>(v) : nullptr;
  return s ? &**s : nullptr;
}
}  // namespace

std::optional<Value> SplineValues::try_parse_rvalue(const Token& first) {
  if (first.kind != TokenKind::identifier) return std::nullopt;
  if (first.is("spline") && peek_raw().is("{")) return Value(Boxed<SplineValue>(parse_block()));
  const Value* found = lookup(first);
  if (!spline_of(found)) return std::nullopt;
  // Held before looking further: the look may end the macro whose local `first` is (`#local L = spline {…} L`
  // as a macro's result, or `M()(0.5)`), after which the name no longer resolves.
  Value held = *found;
  const Token after = peek_raw();   // raw: a directive after `#declare T = S` runs once T is stored
  if (after.is("(")) {   // a call: the value is an expression (S(0.5) + y), its first operand this call
    return Value(parse_additive_after(call(first, std::get<Boxed<SplineValue>>(held))).stored());
  }
  if (after.is("+") || after.is("-") || after.is("*") || after.is("/") || after.is("."))
    fail_expected(after, "'(' and the argument of the spline '" + std::string(first.text) +
                             "' (an incomplete spline call)");
  return held;   // `#declare T = S;`: T is a copy (an immutable value, so shared)
}

SplineValue SplineValues::parse_block() {
  expect("{", " after 'spline'");
  SplineValue s;
  Token start = next();
  if (const SplineValue* base = spline_of(lookup(start))) s = *base;   // spline { S … }
  else unget(start);
  while (const auto type = spline_type_keyword(peek())) {
    s.type = *type;
    next();
  }
  std::size_t entries_given = s.entries.size();
  int terms = s.terms;
  while (true) {
    const Token at = peek();
    if (at.is("}")) break;
    if (spline_type_keyword(at))
      fail_at(at, "the spline type ('" + std::string(at.text) + "') must come before the spline's entries");
    const double t = parse_float();
    accept(",");
    const Token value_at = peek();
    if (value_at.kind == TokenKind::identifier && reserved(value_at) && starts_colour(value_at))
      fail_expected(value_at, "a float or vector value for the spline entry (POV-Ray takes no colour keyword here)");
    if (starts_string(value_at)) fail_expected(value_at, "a float or vector value for the spline entry");
    const Numeric v = parse_expression();
    accept(",");
    std::array<double, 5> value{};
    const int given = v.terms == 1 ? 2 : v.terms;   // a float V is <V, V>, as POV-Ray promotes it
    for (int k = 0; k < given; ++k) value[static_cast<std::size_t>(k)] = v.v[v.terms == 1 ? 0 : k];
    terms = std::max(terms, given);
    insert_spline_entry(s, t, value);
    ++entries_given;
  }
  const Token close = next();
  if (entries_given == 0) fail_expected(close, "a spline entry 'T, V' (a spline needs at least one)");
  s.terms = terms;
  solve_natural_spline(s);
  return s;
}

Numeric SplineValues::call(const Token& name, Boxed<SplineValue> spline) {
  // `spline` is held here: parsing the argument may end the macro or include file whose local it is.
  const std::string what = "the spline '" + std::string(name.text) + "'";
  Token open = next();
  if (!open.is("(")) fail_expected(open, "'(' after " + what + " (a spline is used by calling it: S(t))");
  const double t = parse_float();
  SplineType type = spline->type;
  if (accept(",")) {
    Token word = next();
    const auto chosen = spline_type_keyword(word);
    if (!chosen)
      fail_expected(word, "linear_spline, quadratic_spline, cubic_spline or natural_spline as the type of " + what);
    type = *chosen;
  }
  Token close = next();
  if (!close.is(")")) fail_expected(close, "')' closing the call of " + what);
  const std::array<double, 5> value = evaluate_spline(*spline, type, t);
  Numeric n;
  n.terms = spline->terms;
  for (int k = 0; k < n.terms; ++k) n.v[static_cast<std::size_t>(k)] = value[static_cast<std::size_t>(k)];
  return n;
}

}  // namespace povtrace::sdl

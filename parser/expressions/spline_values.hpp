// SDL spline values (docs/parser-split-plan.md step S8, the splines' part): `spline { … }` definitions, calls
// `S(t [, type])` and copies of a declared spline as right-hand values. Bodies in spline_values.cpp, which says what
// of POV-Ray's Parse_Spline and Parse_Spline_Call they reproduce; the interpolation is runtime/splines.*. No state:
// the token reader, the expressions and the symbols come through ParserPart.
#pragma once

#include <optional>

#include "parser/expressions/values.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class SplineValues : ParserPart {
 public:
  explicit SplineValues(Interpreter& in) : ParserPart(in) {}

  // `spline { … }` (a definition), `S(…)` (a call of a declared spline, and the expression it starts) or `S` (a
  // copy) as a right-hand value; nothing when `first` starts none of them.
  std::optional<Value> try_parse_rvalue(const Token& first);
  // `{ [S] [type…] T, V … }` after the keyword `spline`: the spline it makes (also a function's spline argument).
  SplineValue parse_block();
  // `(t [, type])` after the spline identifier `name`: its value at t.
  Numeric call(const Token& name, Boxed<SplineValue> spline);
};

}  // namespace povtrace::sdl

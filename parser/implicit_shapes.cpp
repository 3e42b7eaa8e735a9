// superellipsoid and blob (povray-sdl-and-geometry.md §8). Facts from POV-Ray 3.7's parser
// (source/backend/parser/parse.cpp Parse_Superellipsoid, express.cpp Parse_UV_Vect, 3.7-stable):
// - superellipsoid { <e, n> modifiers }: the exponents are a UV vector (a float stands for both; three or more
//   components are an error). The shape is |x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) = 1; the renderer derives the
//   powers.
#include "parser/interpreter.hpp"

namespace povtrace::sdl {

// Parse_UV_Vect: a float or a 2-D vector at the parameter level.
std::pair<double, double> Interpreter::parse_uv_vector(std::string_view context) {
  const Token start = peek();
  const Numeric n = parse_additive();
  if (n.terms > 2)
    fail_at(start, "expected a 2-D vector " + std::string(context) + ", found a " + value_type_name(Value(n)));
  return {n.v[0], n.terms == 1 ? n.v[0] : n.v[1]};
}

Object Interpreter::parse_superellipsoid(const Token& keyword) {
  expect("{", " after 'superellipsoid'");
  Object o;
  o.loc = keyword.loc;
  Superellipsoid s;
  std::tie(s.e, s.n) = parse_uv_vector("<e, n> of the superellipsoid");
  o.shape = s;
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl

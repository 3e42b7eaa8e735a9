// poly, cubic, quartic and quadric (POV-Ray's polynomial surfaces). Facts from POV-Ray 3.7's parser (source/backend/parser/
// parse.cpp, Parse_Poly and Parse_Coeffs, 3.7-stable):
// - `poly { N, <c…> }` reads the order first (2…35, else "Order of poly is out of range"); `cubic` and `quartic` are
//   orders 3 and 4. Then exactly (N+1)(N+2)(N+3)/6 coefficients inside < >, commas optional.
// - `sturm` is an object modifier (try_sturm_modifier).
#include "parser/interpreter.hpp"
#include "parser/objects/object_parser.hpp"

namespace povtrace::sdl {

namespace {
constexpr int kMaxPolyOrder = 35;       // POV-Ray's MAX_ORDER

int term_count(int order) { return (order + 1) * (order + 2) * (order + 3) / 6; }
}  // namespace

Object ObjectParser::parse_poly(const Token& keyword, int order) {
  expect("{", " after '" + std::string(keyword.text) + "'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  if (order == 0) {
    const Token at = peek();
    const double n = parse_float();
    accept(",");
    if (!(n >= 2 && n < kMaxPolyOrder + 1)) fail_at(at, "the order of a poly must be 2 to 35");
    order = static_cast<int>(n);
  }
  const Token open = next();
  if (!open.is("<")) fail_expected(open, "'<' starting the " + std::to_string(term_count(order)) + " coefficients");
  auto coefficients = std::make_shared<std::vector<double>>();
  coefficients->reserve(static_cast<std::size_t>(term_count(order)));
  coefficients->push_back(parse_float());
  for (int i = 1; i < term_count(order); ++i) {
    accept(",");
    coefficients->push_back(parse_float());
  }
  if (const Token close = next(); !close.is(">"))
    fail_expected(close, "'>' after the " + std::to_string(term_count(order)) + " coefficients of a poly of order " +
                             std::to_string(order));
  Poly poly;
  poly.order = order;
  poly.coefficients = std::move(coefficients);
  o.shape = poly;
  parse_object_modifiers(o);
  return o;
}

// quadric { <A,B,C>, <D,E,F>, <G,H,I>, J } (POV-Ray's Parse_Quadric): square, mixed and linear terms, then the
// constant; commas optional.
Object ObjectParser::parse_quadric(const Token& keyword) {
  expect("{", " after 'quadric'");
  if (auto declared = parse_declared_object_body()) return std::move(*declared);   // Parse_Object_Id
  Object o;
  o.loc = keyword.loc;
  Quadric q;
  q.square = parse_vector();
  accept(",");
  q.mixed = parse_vector();
  accept(",");
  q.linear = parse_vector();
  accept(",");
  q.constant = parse_float();
  o.shape = q;
  extents().made(o);
  parse_object_modifiers(o);
  return o;
}

}  // namespace povtrace::sdl

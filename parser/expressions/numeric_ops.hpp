// The arithmetic of SDL values that both expression engines compute with — the recursive descent
// (expressions.cpp) and the expression programs (expression_programs.cpp) — so that the two cannot differ:
// comparisons with POV-Ray's tolerance and the promotion of floats and shorter vectors
// (povray-sdl-and-geometry.md §5).
#pragma once

#include <algorithm>
#include <cmath>
#include <string_view>

#include "parser/expressions/values.hpp"
#include "parser/lexing/lexer.hpp"

namespace povtrace::sdl {

constexpr double kEqualEpsilon = 1e-10;   // '=' and '!=' compare with |a−b| ≤ 1e-10 (§5)

enum class Comparison { none, less, greater, less_equal, greater_equal, equal, not_equal };

inline Comparison comparison_of(TokenKind kind, std::string_view s) {
  // By the bytes, not by six string comparisons: asked after every operand at the full level.
  if (kind != TokenKind::symbol || s.empty() || s.size() > 2) return Comparison::none;
  const char a = s[0];
  if (s.size() == 1)
    return a == '<' ? Comparison::less : a == '>' ? Comparison::greater : a == '=' ? Comparison::equal
                                                                                   : Comparison::none;
  if (s[1] != '=') return Comparison::none;
  return a == '<' ? Comparison::less_equal : a == '>' ? Comparison::greater_equal
                                           : a == '!' ? Comparison::not_equal : Comparison::none;
}

// '=' and its kin compare with a tolerance (§5).
inline bool compare(Comparison c, double a, double b) {
  const bool near = std::fabs(a - b) <= kEqualEpsilon;
  switch (c) {
    case Comparison::less: return a < b;
    case Comparison::greater: return a > b;
    case Comparison::less_equal: return a < b || near;
    case Comparison::greater_equal: return a > b || near;
    case Comparison::equal: return near;
    case Comparison::not_equal: return !near;
    case Comparison::none: break;
  }
  return false;
}

// Promotes the shorter operand: a float broadcasts, a shorter vector is zero-padded (§5).
inline void promote(Numeric& a, Numeric& b) {
  const int terms = std::max(a.terms, b.terms);
  auto widen = [terms](Numeric& n) {
    if (n.terms == terms) return;
    if (n.terms == 1) for (int i = 1; i < terms; ++i) n.v[i] = n.v[0];
    n.terms = terms;
  };
  widen(a);
  widen(b);
  a.colour = b.colour = a.colour || b.colour;
}

template <class Op> Numeric componentwise(Numeric a, Numeric b, Op op) {
  promote(a, b);
  for (int i = 0; i < a.terms; ++i) a.v[i] = op(a.v[i], b.v[i]);
  return a;
}

inline Numeric promoted_to(Numeric n, int terms) {
  if (n.terms == 1) for (int i = 1; i < terms; ++i) n.v[i] = n.v[0];
  n.terms = std::max(n.terms, terms);
  return n;
}

}  // namespace povtrace::sdl

// Features povtrace parses but does not render yet. Issue 3 asks that every standard include file and scene
// parse whole, and that the "unsupported" error come only when such a feature reaches the rendered scene. So an
// item povtrace cannot render is consumed structurally — its braces, brackets and argument expressions, with
// directives and macro calls inside still executed as POV-Ray would — and the value it belongs to is tainted with
// an UnsupportedFeature naming it. Placing a tainted value in the scene is the error (refuse_if_unsupported).
#include "parser/interpreter.hpp"
#include "parser/statements/unsupported_features.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
// Reserved words that are values inside argument expressions, not the start of the next item.
bool is_value_word(std::string_view w) {
  static const std::string_view words[] = {"x", "y", "z", "t", "u", "v", "pi", "true", "false", "yes", "no",
                                           "on", "off", "version", "clock", "clock_on", "clock_delta", "tau",
                                           "now"};
  for (auto v : words)
    if (w == v) return true;
  return false;
}

std::string_view closer_of(std::string_view open) { return open == "{" ? "}" : open == "(" ? ")" : "]"; }
}  // namespace

void UnsupportedFeatures::skip_balanced(const Token& open) {
  std::vector<std::string_view> expected{closer_of(open.text)};
  while (!expected.empty()) {
    Token t = next();
    if (t.kind == TokenKind::end_of_input)
      fail_expected(t, "'" + std::string(expected.back()) + "' closing the '" + std::string(open.text) + "' at " +
                           open.loc.to_string());
    if (t.is("{") || t.is("(") || t.is("[")) expected.push_back(closer_of(t.text));
    else if (t.is("}") || t.is(")") || t.is("]")) {
      if (!t.is(expected.back()))
        fail_expected(t, "'" + std::string(expected.back()) + "' (brackets do not match)");
      expected.pop_back();
    }
  }
}

// Whether `t` still belongs to the arguments of the item being skipped.
bool UnsupportedFeatures::continues_arguments(const Token& t) {
  // A closer that was not opened while skipping ends the enclosing construct (a pigment_map entry's ']').
  if (t.kind == TokenKind::end_of_input || t.is("}") || t.is("]") || t.is(")")) return false;
  if (t.kind != TokenKind::identifier || !is_reserved_word(t.text) || is_value_word(t.text)) return true;
  // A reserved word followed by '(' is a function call inside an expression (sin(…), vrotate(…)).
  return peek().is("(");
}

// An item is either `keyword { … }` (the block is the whole item) or `keyword arguments…`, the arguments running
// to the next keyword that starts an item, a ';' or the enclosing '}'.
UnsupportedFeature UnsupportedFeatures::skip_unsupported(const Token& keyword, const std::string& what) {
  Token first = next();
  if (first.is("{")) {
    skip_balanced(first);
    return UnsupportedFeature{what, keyword.loc};
  }
  unget(first);
  while (true) {
    Token t = next();
    if (t.is("{") || t.is("(") || t.is("[")) { skip_balanced(t); continue; }
    if (t.is(";") || !continues_arguments(t)) { unget(t); break; }
  }
  return UnsupportedFeature{what, keyword.loc};
}

void UnsupportedFeatures::refuse_if_unsupported(const Unsupported& u, const SourceLoc& placed_at,
                                                std::string_view what) const {
  if (!u) return;
  std::string message = "unsupported: " + u->name + " is a POV-Ray feature that povtrace does not render yet";
  if (u->loc.line != placed_at.line || u->loc.file != placed_at.file || u->loc.column != placed_at.column)
    message += " (written at " + u->loc.to_string() + ", used by this " + std::string(what) + ")";
  fail(placed_at, message);
}

}  // namespace povtrace::sdl

#include "parser/lexing/diagnostics.hpp"

#include <iostream>

namespace povtrace::sdl {

void Diagnostics::fail(const SourceLoc& loc, const std::string& message) const { throw stream_.error(loc, message); }

void Diagnostics::fail_at(const Token& t, const std::string& message) const { fail(t.loc, message); }

std::string Diagnostics::describe(const Token& t) const {
  switch (t.kind) {
    case TokenKind::end_of_input: return "the end of the file";
    case TokenKind::number: return "the number " + std::string(t.text);
    case TokenKind::string: return "the string " + std::string(t.text);
    case TokenKind::identifier:
      if (reserved(symbols_, t)) return "the keyword '" + std::string(t.text) + "'";
      if (const Value* v = lookup(symbols_, t))
        return "the " + value_type_name(*v) + " identifier '" + std::string(t.text) + "'";
      return "the undeclared identifier '" + std::string(t.text) + "'";
    case TokenKind::symbol: return "'" + std::string(t.text) + "'";
  }
  return "?";
}

void Diagnostics::fail_expected(const Token& t, std::string_view expected) const {
  fail_at(t, "expected " + std::string(expected) + ", found " + describe(t));
}

void Diagnostics::fail_unsupported(const Token& t, std::string_view what) const {
  fail_at(t, "unsupported: " + std::string(what) + " is a POV-Ray feature that povtrace does not render yet");
}

void Diagnostics::warn(const SourceLoc& loc, const std::string& message) const {
  if (options_.warning_level < 5) return;
  std::string text = format_diagnostic(loc, "warning", message, stream_.file_of(loc).line_text(loc.line));
  if (const std::string chain = stream_.reached_from(); !chain.empty()) text += "\n" + chain;
  if (options_.classified_sink) options_.classified_sink(ParseOptions::MessageKind::warning, text);
  else if (options_.message_sink) options_.message_sink(text);
  else std::cerr << text << "\n";
}

}  // namespace povtrace::sdl

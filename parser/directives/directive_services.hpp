// DirectiveRunner's forwarders to the Interpreter services it still uses (directive_runner.hpp lists them: the
// interface to narrow when the reader and expression parts exist, S5/S7). Included by the runner's .cpp files
// only: here the Interpreter is complete.
#pragma once

#include "parser/directives/directive_runner.hpp"
#include "parser/interpreter.hpp"

namespace povtrace::sdl {

inline Token DirectiveRunner::next() { return in_.next(); }
inline const Token& DirectiveRunner::peek() { return in_.peek(); }
inline const Token& DirectiveRunner::peek_raw() { return in_.peek_raw(); }
inline Token DirectiveRunner::expect(std::string_view symbol, std::string_view context) {
  return in_.expect(symbol, context);
}
inline bool DirectiveRunner::accept(std::string_view symbol) { return in_.accept(symbol); }
inline void DirectiveRunner::skip_expected(char symbol, std::string_view context) {
  in_.skip_expected(symbol, context);
}
inline std::string DirectiveRunner::expect_identifier_raw(std::string_view context) {
  return in_.expect_identifier_raw(context);
}
inline const LexedToken* DirectiveRunner::plain_ahead() { return in_.plain_ahead(); }
inline void DirectiveRunner::consume_plain() { in_.consume_plain(); }
inline auto DirectiveRunner::raw_ahead() { return in_.raw_ahead(); }
inline void DirectiveRunner::skip_ahead() { in_.skip_ahead(); }
inline const Value* DirectiveRunner::lookup(const Token& t) const { return in_.lookup(t); }
inline double DirectiveRunner::parse_float() { return in_.parse_float(); }
inline double DirectiveRunner::parse_float_full() { return in_.parse_float_full(); }
inline Numeric DirectiveRunner::parse_additive() { return in_.parse_additive(); }
inline Numeric DirectiveRunner::parse_expression() { return in_.parse_expression(); }
inline std::string DirectiveRunner::parse_string() { return in_.parse_string(); }
inline bool DirectiveRunner::starts_string(const Token& t) const { return in_.starts_string(t); }
inline std::optional<Value> DirectiveRunner::try_parse_rvalue(const Token& first) {
  return in_.try_parse_rvalue(first);
}
inline bool DirectiveRunner::numeric_ahead() { return in_.numeric_ahead(); }
inline void DirectiveRunner::call_macros_ahead() { in_.call_macros_ahead(); }
inline bool DirectiveRunner::parse_defined_identifier() { return in_.arrays_.parse_defined_identifier(); }
inline auto DirectiveRunner::parse_element_reference(const Token& name) {
  return in_.arrays_.parse_element_reference(name);
}
inline void DirectiveRunner::store_element(ArrayValue& a, std::size_t index, Value value, const Token& at,
                                           const std::string& name) {
  in_.arrays_.store_element(a, index, std::move(value), at, name);
}
inline void DirectiveRunner::directive_declare_element(const Token& name, bool local) {
  in_.arrays_.directive_declare_element(name, local);
}
inline void DirectiveRunner::check_function_redeclaration(const Token& name, bool local, const Value& value) {
  in_.functions_.check_redeclaration(name, local, value);
}
inline void DirectiveRunner::parse_default(const Token& keyword) { in_.parse_default(keyword); }
inline void DirectiveRunner::directive_version(const Token& at) { in_.directive_version(at); }
inline int DirectiveRunner::language_version() const { return in_.scene_.language_version; }

}  // namespace povtrace::sdl

// DirectiveRunner's forwarders to the Interpreter services it still uses (directive_runner.hpp lists them: the
// interface to narrow when the reader and expression parts exist, S5/S7). Included by the runner's .cpp files
// only: here the Interpreter is complete.
#pragma once

#include "parser/directives/directive_runner.hpp"
#include "parser/interpreter.hpp"

namespace povtrace::sdl {

inline bool DirectiveRunner::numeric_ahead() { return values_.numeric_ahead(); }
inline void DirectiveRunner::call_macros_ahead() { values_.call_macros_ahead(); }
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
inline void DirectiveRunner::parse_default(const Token& keyword) { in_.statements_.parse_default(keyword); }
inline void DirectiveRunner::directive_version(const Token& at) { in_.statements_.directive_version(at); }

}  // namespace povtrace::sdl

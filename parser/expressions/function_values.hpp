// SDL user-defined functions as values (docs/parser-split-plan.md step S8, the functions' part): `function { … }`
// definitions, calls `F(a, b, c)` in SDL expressions, copies of a declared function, and the rule that a function
// must be #undef'd before its name is declared again (§3). Bodies in function_parser.cpp, whose FunctionParser
// reads a definition's body through this part; the evaluator is runtime/function_vm.cpp. It owns the budget of
// function evaluation under ParseOptions::max_tokens, shared by every call of the parse and the height_field
// functions.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>

#include "parser/expressions/values.hpp"
#include "parser/parse_scene.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class SplineValues;
class SymbolTable;
class TextureParser;

class FunctionValues : ParserPart {
 public:
  // `clock` inside a function body is the frame's clock, a constant (POV-Ray's fnsyntax.cpp).
  double clock() const { return options_.clock.value_or(0.0); }
  FunctionValues(Interpreter& in, const ParseOptions& options, SymbolTable& symbols, TextureParser& textures,
                 SplineValues& splines)
      : ParserPart(in), options_(options), symbols_(symbols), textures_(textures), splines_(splines) {}

  // `function …` (a definition), `F(…)` (a call of a declared function) or `F` (a copy) as a right-hand value.
  std::optional<Value> try_parse_rvalue(const Token& first);
  // `(a, b, …)` after the declared function `name`: its value (a float, a vector or a colour).
  Numeric call(const Token& name, std::shared_ptr<const FunctionValue> fn);
  // `function [(params)] { … }` after its keyword: the compiled function.
  std::shared_ptr<const FunctionValue> parse_definition(const Token& keyword);
  // #declare/#local of `name`: a function must be #undef'd before its name is declared again (§3).
  void check_redeclaration(const Token& name, bool local, const Value& value);
  // What function evaluation may still do under ParseOptions::max_tokens (the fuzzer's bound on function work),
  // set on first use; null without a token limit. For evaluate_function's `steps`.
  std::uint64_t* budget() {
    if (options_.max_tokens && !function_budget_set_) {
      function_steps_left_ = options_.max_tokens * 16;   // shared by every call of the parse
      function_budget_set_ = true;
    }
    return options_.max_tokens ? &function_steps_left_ : nullptr;
  }

 private:
  friend class FunctionParser;   // reads the definition's tokens, textures and splines through this part
  // The renderer's pattern values for pattern functions (ParseOptions::pattern_evaluator); may be null.
  const PatternEvaluator* pattern_evaluator() const { return options_.pattern_evaluator.get(); }

  const ParseOptions& options_;
  SymbolTable& symbols_;
  TextureParser& textures_;
  SplineValues& splines_;
  std::uint64_t function_steps_left_ = 0;   // with ParseOptions::max_tokens: what function evaluation may still do
  bool function_budget_set_ = false;
};

}  // namespace povtrace::sdl

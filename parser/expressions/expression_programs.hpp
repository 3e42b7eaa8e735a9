// Expression programs (docs/parser-split-plan.md step S6): loops and macro bodies read the same expressions over
// and over from the same kept tokens. The first time one is met again it is translated into a program (numbers,
// numeric identifiers, + - * / unary ! comparisons & |, parentheses, vector literals, pure built-in float calls),
// which later readings run instead of parsing it: the grammar decides the program from the tokens alone, and the
// values are checked as it runs. Anything the program does not cover — a '#' or the end of a file on the way, a
// string, a macro, an identifier that holds no number when read, an error or warning the parse would give — leaves
// it to the full parse (expressions.cpp), which starts from the same token and reports it: nothing is consumed
// before the program has its value. expression_programs.cpp says why there are two engines.
//
// The part owns the programs; it reads the token stream's kept tokens and notes, the symbols, the options and
// whether the directives are replaying. The nesting level is the reader's, passed to run(): the full parse's
// NestingGuard, which a program passes by, stays exact by leaving expressions near the limit to the full parse.
#pragma once

#include <cstdint>
#include <vector>

#include "parser/directives/symbols.hpp"
#include "parser/expressions/values.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/parse_scene.hpp"

namespace povtrace::sdl {

class DirectiveRunner;
struct FloatFunction;

class ExpressionPrograms {
 public:
  struct ExpressionOp {
    enum class Code : std::uint8_t {
      number, name, neg, not_, add, sub, mul, div, compare, and_, or_, vector, call
    } code = Code::number;
    std::uint8_t arg = 0;       // compare: the Comparison; vector, call: the component or argument count
    std::uint32_t name = 0;     // name: the NameId
    double number = 0;          // number: the value
    const FloatFunction* function = nullptr;   // call: the built-in
  };
  struct ExpressionProgram {
    std::uint32_t first_op = 0, op_count = 0;   // in program_ops_
    std::uint32_t end = 0;                      // token index just after the expression
    bool usable = false;                        // false: the grammar took something no program covers
  };
  // Nesting levels a program's expression may pass by: the caller runs it only where that many more fit.
  static constexpr int kNestingDepth = 16;

  // Built with the parts it reads, which it does not use before the first run().
  ExpressionPrograms(const ParseOptions& options, TokenStream& stream, const SymbolTable& symbols,
                     const DirectiveRunner& directives);
  ExpressionPrograms(const ExpressionPrograms&) = delete;
  ExpressionPrograms& operator=(const ExpressionPrograms&) = delete;

  // The expression at the frame's next token at the full level (parse_expression: full) or the parameter level
  // (parse_additive), run as a program where one exists or can be made now: its value in `out` and the stream
  // past it. False, having read nothing, elsewhere, and where `nesting` (the reader's NestingGuard level) leaves
  // no room for kNestingDepth more levels. One call per expression, as the parse asks at every one.
  bool run(bool full, Numeric& out, int nesting);

 private:
  class ProgramCompiler;

  // ParseOptions::expression_programs, and no token limit (with one, next() counts every token); read once.
  const bool enabled_;
  TokenStream& stream_;
  const SymbolTable& symbols_;
  const DirectiveRunner& directives_;
  std::vector<ExpressionProgram> programs_;
  std::vector<ExpressionOp> program_ops_;
};

}  // namespace povtrace::sdl

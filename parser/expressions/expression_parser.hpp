// The SDL expression parser (docs/parser-split-plan.md step S7): float, vector, colour and string expressions at
// POV-Ray's two levels (parameter level = additive, Parse_Float; full level with comparisons, & | and ?: inside
// parentheses and conditions, Parse_Float_Param's inner level), the built-in functions (functions.cpp) and their
// rand() streams, Parse_UV_Vect and Allow_Float. POV-Ray parses and evaluates in one pass, so this is the one
// engine that defines an expression's value; the replayed ones it first hands to the ExpressionPrograms part
// (expression_programs.hpp), a memo of it. Bodies in expressions.cpp and functions.cpp.
//
// A ParserPart: the token reader and diagnostics come through ParserPart. Its fast paths read the kept tokens and
// the symbols straight (fast_operand, ExpressionStart, string_ahead), as next() would find them; it calls the
// value parts for what an operand may be (a function or spline call, dimensions(), inside(), trace(), defined()).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "parser/expressions/builtins.hpp"
#include "parser/expressions/values.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/parse_scene.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class ArrayValues;
class DirectiveRunner;
class ExpressionPrograms;
class FunctionValues;
class ObjectQueries;
class SplineValues;
class SymbolTable;

class ExpressionParser : ParserPart {
 public:
  // Built with the parts it reads, which it does not use before the parse starts.
  ExpressionParser(Interpreter& in, const ParseOptions& options,
                   ExpressionPrograms& programs, const DirectiveRunner& directives, ArrayValues& arrays,
                   ObjectQueries& object_queries, FunctionValues& functions, SplineValues& splines)
      : ParserPart(in), token_limit_(options.max_tokens != 0), programs_(programs), directives_(directives),
        arrays_(arrays), object_queries_(object_queries), functions_(functions), splines_(splines) {}

  Numeric parse_expression();            // full level: ?:, & |, comparisons, + -
  Numeric parse_additive();              // parameter level (Parse_Rel_Factor)
  // The rest of an additive expression whose first operand the caller has already read (a call of a function or
  // spline it held, the identifier of which may no longer resolve): its postfix, then * / and + - as usual.
  Numeric parse_additive_after(Numeric first_operand);
  double parse_float();
  double parse_float_full();             // a float at the full level (inside parentheses semantics)
  Vec3 parse_vector();
  Colour parse_colour();                 // Parse_Colour: optional colour keyword, forms, overrides
  bool starts_colour(const Token& t) const;
  std::string parse_string();
  bool starts_string(const Token& t) const;
  // POV-Ray's Parse_UV_Vect: a float or a 2-D vector at the parameter level (superellipsoid, uv_vectors, sweep
  // profile points, image_map repeat and offset).
  std::pair<double, double> parse_uv_vector(std::string_view context);
  // POV-Ray's Allow_Float: a float expression if one follows (object modifiers, finishes, maps), else `fallback`.
  double optional_float(double fallback);

 private:
  using Frame = TokenStream::Frame;
  class ExpressionStart;

  Numeric parse_multiplicative();
  Numeric parse_additive_rest(Numeric value);         // + - after the operand `value`
  Numeric parse_multiplicative_rest(Numeric value);   // * / after the operand `value`
  Numeric parse_unary();
  Numeric parse_postfix(Numeric value);
  Numeric parse_primary(const Token& t);   // t: the operand's first token, already read
  Numeric parse_vector_literal(const Token& open);
  Numeric parse_colour_keyword_form(const Token& keyword);
  Numeric parse_function_call(const Token& name);
  std::string parse_datetime();
  Numeric compare_strings();   // "a" < "b" and the other comparisons of two strings
  static int strcmp_value(const std::string& a, const std::string& b);   // POV-Ray's strcmp(): a char difference
  bool string_ahead();   // starts_string() of what comes next, made a Token only where needed
  double to_float(const Numeric& n, const Token& at) const;
  CallArguments parse_call_arguments(const Token& name, std::size_t min_args, std::size_t max_args);
  static bool is_float_function(std::string_view name);   // abs, sin, … (the built-ins that return a float)
  // A number or a numeric identifier as a whole operand, read from the kept tokens without a Token (most operands
  // are one); false, having read nothing, where the full parse_unary() must run.
  bool fast_operand(Numeric& out);
  // The expression ahead run as a compiled program (expression_programs.hpp), where one exists and the nesting
  // limit has room for the levels it passes by; false, having read nothing, elsewhere.
  inline bool run_expression_program(bool full, Numeric& out);

  // The kept-token reads of the fast paths, from the stream.
  Token make_token(const FileTokens& tokens, const LexedToken& t) const {
    return token_stream().make_token(tokens, t);
  }
  std::string_view text_of(const LexedToken& k) const { return token_stream().text_of(k); }
  const SourceFile& file_of(const SourceLoc& loc) const { return token_stream().file_of(loc); }

  // ParseOptions::max_tokens set: next() counts every token, so the fast paths that read kept tokens are off. Read
  // once (an options reference read per operand cost instructions on the parse benchmarks).
  const bool token_limit_;
  ExpressionPrograms& programs_;
  const DirectiveRunner& directives_;   // file_exists() asks its include search
  ArrayValues& arrays_;
  ObjectQueries& object_queries_;
  FunctionValues& functions_;
  SplineValues& splines_;
  std::vector<std::uint32_t> rand_streams_;   // seed() and rand(): POV-Ray's streams, by the number seed() returns
};

}  // namespace povtrace::sdl

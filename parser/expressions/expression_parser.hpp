// The SDL expression parser (docs/parser-split-plan.md step S7): float, vector, colour and string expressions at
// POV-Ray's two levels (parameter level = additive, Parse_Float; full level with comparisons, & | and ?: inside
// parentheses and conditions, Parse_Float_Param's inner level), the built-in functions (functions.cpp) and their
// rand() streams, Parse_UV_Vect and Allow_Float. POV-Ray parses and evaluates in one pass, so this is the one
// engine that defines an expression's value; the replayed ones it first hands to the ExpressionPrograms part
// (expression_programs.hpp), a memo of it. Bodies in expressions.cpp and functions.cpp.
//
// Not a ParserPart member like the other parts but an empty base of the Interpreter (CRTP-style): the grammar's
// functions are the hottest callers of the token reader, and a part reaches the reader through its stored
// Interpreter reference, which GCC reloads from `this` after every call and holds in one more callee-saved register
// (measured: 0.3-0.8% more instructions on the parse benchmarks). As an empty base it sits at the Interpreter's
// address, as the reader (its first member) does, so in() is `this` and the reader is reached with no load. It
// keeps no state: its rand() streams and token-limit flag are the Interpreter's, the value parts it calls are the
// Interpreter's members, all reached through in(). The reader and diagnostics come through its own one-line
// forwarders below, of the same names as ParserPart's (bodies in parser_part_forwarders.hpp). Its fast paths read
// the kept tokens and the symbols straight (fast_operand, ExpressionStart, string_ahead), as next() would find
// them; it calls the value parts for what an operand may be (a function or spline call, dimensions(), inside(),
// trace(), defined()).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "parser/expressions/builtins.hpp"
#include "parser/expressions/values.hpp"
#include "parser/lexing/token_reader.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/parse_scene.hpp"

namespace povtrace::sdl {

class Interpreter;
class SymbolTable;

class ExpressionParser {
 public:
  static bool is_float_function(std::string_view name);   // abs, sin, … (the built-ins that return a float)
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

 protected:
  ExpressionParser() = default;   // only as the Interpreter's base
  ~ExpressionParser() = default;
  ExpressionParser(const ExpressionParser&) = delete;
  ExpressionParser& operator=(const ExpressionParser&) = delete;

 private:
  using Frame = TokenStream::Frame;
  class ExpressionStart;

  // The Interpreter this is the base of: a fixed offset from `this` (none, with the empty base), not a load.
  inline Interpreter& in();
  inline const Interpreter& in() const;
  inline TokenReader& reader();
  inline const TokenReader& reader() const;

  // ---- token reader and diagnostics: ParserPart's forwarders of the same names, through in() ----
  inline Token next();
  inline const Token& peek();   // valid until the next token is read
  inline void unget(const Token& t);
  inline Token expect(std::string_view symbol, std::string_view context);
  inline bool accept(std::string_view symbol);   // consumes the token if it is `symbol`
  inline const Value* lookup(const Token& t) const;
  inline const Token& peek_raw();   // the next token without running a directive or macro call first
  inline bool reserved(const Token& t) const;
  inline Token raw();   // the next token with no directive processing
  struct NestingGuard : TokenReader::NestingGuard {   // the reader's own (same checks, same message)
    using RoomChecked = TokenReader::NestingGuard::RoomChecked;
    inline NestingGuard(ExpressionParser& part, const Token& at);
    inline NestingGuard(ExpressionParser& part, RoomChecked room);
  };
  inline const LexedToken* plain_ahead();
  inline void consume_plain();
  inline bool plain_symbol(const LexedToken* k, char c) const;
  inline void skip_expected(char symbol, std::string_view context);   // expect() without making its Token
  inline TokenReader::Ahead raw_ahead();   // kind and text of what peek_raw() would return
  inline void skip_ahead();
  inline bool nesting_room() const;
  inline int nesting() const;
  inline TokenStream& token_stream();
  inline const TokenStream& token_stream() const;
  inline const SymbolTable& symbol_table() const;
  [[noreturn]] inline void fail(const SourceLoc& loc, const std::string& message) const;
  [[noreturn]] inline void fail_at(const Token& t, const std::string& message) const;
  [[noreturn]] inline void fail_expected(const Token& t, std::string_view expected) const;
  [[noreturn]] inline void fail_unsupported(const Token& t, std::string_view what) const;
  inline void warn(const SourceLoc& loc, const std::string& message) const;
  inline void refuse_if_unsupported(const Unsupported& u, const SourceLoc& placed_at, std::string_view what) const;
  // The scene's settings so far, which the image functions' gamma handling reads.
  inline int language_version() const;
  inline const ParseOptions& parse_options() const;
  inline const std::optional<double>& assumed_gamma() const;

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
};

}  // namespace povtrace::sdl

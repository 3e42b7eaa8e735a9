// The base of the parser's components (docs/parser-split-plan.md §2): a part holds the Interpreter and reaches the
// services it needs — the token reader, diagnostics, the expression parser, the statements' language settings —
// through the protected one-line forwarders below, so that a part's bodies read as they did in the Interpreter
// (`next()`, `expect(…)`, `fail_at(…)`, `parse_float()`, `NestingGuard guard(*this, keyword)`). Each forwarder goes
// to the part that provides the service (the TokenReader, the Diagnostics, the ExpressionParser, SceneStatements…),
// reached through the Interpreter that owns them all.
//
// Only the services a part uses are forwarded; each is a plain inline call (no virtual call), defined in
// parser_part_forwarders.hpp once the Interpreter is complete (interpreter.hpp includes it at its end).
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "parser/expressions/values.hpp"
#include "parser/extents/object_extents.hpp"
#include "parser/extents/object_notes.hpp"
#include "parser/lexing/lexer.hpp"
#include "scene/description.hpp"
#include "scene/description_transforms.hpp"

namespace povtrace::sdl {

class Interpreter;
class SymbolTable;
class TokenStream;
class ObjectExtents;
class TokenReader;
class ParserPart;

// A NestingGuard taken by a part: the TokenReader's own (same checks, same message), reached through the part.
// A template only so that the reader's nested guard is named where it is complete (at the guard's use).
template <class In> class PartNestingGuard {
 public:
  PartNestingGuard(ParserPart& part, const Token& at);
  // One more level where nesting_room() has just said there is room (the expressions' plain '(').
  using RoomChecked = typename In::NestingGuard::RoomChecked;
  PartNestingGuard(ParserPart& part, RoomChecked);
  PartNestingGuard(const PartNestingGuard&) = delete;
  PartNestingGuard& operator=(const PartNestingGuard&) = delete;

 private:
  typename In::NestingGuard guard_;
};

// The TokenReader's RawOperatorLook taken by a part (array initialisers, element assignments): the same flag.
template <class In> class PartRawOperatorLook {
 public:
  explicit PartRawOperatorLook(ParserPart& part, bool raw = true);
  PartRawOperatorLook(const PartRawOperatorLook&) = delete;
  PartRawOperatorLook& operator=(const PartRawOperatorLook&) = delete;

 private:
  typename In::RawOperatorLook look_;
};

class ParserPart {
 protected:
  explicit ParserPart(Interpreter& in) : in_(in) {}
  ~ParserPart() = default;
  ParserPart(const ParserPart&) = delete;
  ParserPart& operator=(const ParserPart&) = delete;

  // ---- token reader (TokenReader, lexing/token_reader.hpp) ----
  inline Token next();
  inline const Token& peek();   // valid until the next token is read
  inline void unget(const Token& t);
  inline Token expect(std::string_view symbol, std::string_view context);
  inline bool accept(std::string_view symbol);   // consumes the token if it is `symbol`
  inline const Value* lookup(const Token& t) const;
  inline const Token& peek_raw();   // the next token without running a directive or macro call first
  inline bool reserved(const Token& t) const;
  inline Token raw();                                // the next token with no directive processing (#ifdef's name)
  inline bool ahead_is(std::string_view symbol);     // a raw look at the next token
  inline Token pop_pushed_back();                    // the token a peek_raw() pushed back
  using NestingGuard = PartNestingGuard<TokenReader>;
  // The kept-token reads of the fast paths (token_reader.hpp says what each may skip), without making Tokens: the
  // directives' and the plain-symbol look at an object's closing brace.
  inline const LexedToken* plain_ahead();
  inline void consume_plain();
  inline bool plain_symbol(const LexedToken* k, char c) const;
  inline std::string_view text_of(const LexedToken& k) const;   // a kept token's text
  inline const LexedToken& lexed(FileTokens& tokens, std::size_t index);   // token `index` of a file
  inline void skip_expected(char symbol, std::string_view context);   // expect() without making its Token
  inline std::string expect_identifier_raw(std::string_view context);
  inline auto raw_ahead();   // the reader's Ahead: kind and text of what peek_raw() would return
  inline void skip_ahead();
  using RawOperatorLook = PartRawOperatorLook<TokenReader>;

  // ---- diagnostics (Diagnostics) ----
  [[noreturn]] inline void fail(const SourceLoc& loc, const std::string& message) const;
  [[noreturn]] inline void fail_at(const Token& t, const std::string& message) const;
  [[noreturn]] inline void fail_expected(const Token& t, std::string_view expected) const;
  [[noreturn]] inline void fail_unsupported(const Token& t, std::string_view what) const;
  inline void warn(const SourceLoc& loc, const std::string& message) const;

  // ---- expressions (the ExpressionParser, expressions/expression_parser.hpp) ----
  inline Numeric parse_expression();
  inline Numeric parse_additive();
  inline Numeric parse_additive_after(Numeric first_operand);
  inline bool starts_string(const Token& t) const;
  inline double parse_float();
  inline double parse_float_full();   // a float at the full level (?:, comparisons)
  inline Vec3 parse_vector();
  inline Colour parse_colour();
  inline bool starts_colour(const Token& t) const;
  inline std::string parse_string();
  inline double optional_float(double fallback);   // `[float]`: the float if one starts here, else `fallback`
  // Parse_UV_Vect (express.cpp): a float or a 2-D vector at the parameter level; also read by the shapes.
  inline std::pair<double, double> parse_uv_vector(std::string_view context);
  inline std::shared_ptr<const FunctionValue> parse_function_definition(const Token& keyword);
  // The fuzzer's bound on function work (ParseOptions::max_tokens), shared by every function evaluated during the
  // parse (FunctionValues::budget): height_field { function } evaluates one over its grid. Null without a limit.
  inline std::uint64_t* function_budget();
  // A right-hand value: a number, string, array, object, function… (the ValueReader's).
  inline std::optional<Value> try_parse_rvalue(const Token& first);
  // The reader's nesting level and room (the TokenReader's NestingGuard count), which only the expressions' fast
  // paths and their programs ask.
  inline bool nesting_room() const;
  inline int nesting() const;
  // The token stream and the symbols as the expressions' fast paths read them (kept tokens, NameIds): reached
  // through the Interpreter, whose first member the stream is, so that they cost no reference of their own.
  inline TokenStream& token_stream() const;
  inline const SymbolTable& symbol_table() const;

  // ---- objects (ObjectParser) ----
  inline std::optional<SceneItem> try_parse_item(const Token& t);
  inline void parse_object_modifiers(Object& object);
  inline void apply_transform(Object& object, const Matrix& m, TransformKind kind = TransformKind::other);
  inline const NotesPool& notes_pool() const;   // where the objects' notes are made (ObjectNotes)
  // POV-Ray's bounding boxes of objects as they are made and modified (object_extents.hpp): they read the options'
  // object geometry, the noise generator in force and the notes pool, which are not the object parser's.
  inline ObjectExtents extents() const;

  // ---- features parsed but not rendered (unsupported.cpp) ----
  inline UnsupportedFeature skip_unsupported(const Token& keyword, const std::string& what);
  inline void skip_balanced(const Token& open);
  // An identifier holding a value parsed but not supported (an OpaqueValue) used in an expression: refused by name.
  inline void refuse_if_unsupported(const Unsupported& u, const SourceLoc& placed_at, std::string_view what) const;
  static inline void taint(Unsupported& slot, const Unsupported& feature);   // keeps the first one found

  // ---- radiosity (RadiosityParser, statements/radiosity_parser.hpp) ----
  // `radiosity { importance F }` of an object or #default: the last importance written, if any.
  inline std::optional<double> parse_radiosity_importance(const Token& keyword);

  // ---- the scene's settings so far (SceneStatements) ----
  inline const Texture& default_texture() const;   // the #default texture
  // What POV-Ray's image gamma handling reads: the language version (round(100 · #version), 370 when no #version
  // was seen), whether any #version was seen (languageVersionSet) and global_settings' assumed_gamma.
  inline int language_version() const;
  inline bool version_directive_seen() const;
  inline const std::optional<double>& assumed_gamma() const;
  inline const std::vector<std::filesystem::path>& library_paths() const;   // +L, for image files
  inline bool povray_tolerances() const;                                     // ParseOptions::povray_tolerances
  inline int noise_generator() const;   // the scene's noise generator in force now (functions evaluated now read it)
  // An object or light finished by `object { }` as a statement, joining the scene.
  inline void place_object(Object&& object, const SourceLoc& at);
  inline void place_light(Light light, const SourceLoc& at);

 private:
  template <class> friend class PartNestingGuard;
  template <class> friend class PartRawOperatorLook;
  Interpreter& in_;
};

}  // namespace povtrace::sdl

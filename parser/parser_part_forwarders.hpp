// The bodies of ParserPart's forwarders (parser_part.hpp): one inline call each, to the Interpreter that provides
// the service today. Included at the end of interpreter.hpp, where the Interpreter is complete.
#pragma once

#include <type_traits>

#include "parser/interpreter.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

template <class In>
PartNestingGuard<In>::PartNestingGuard(ParserPart& part, const Token& at) : guard_(part.in_.reader_, at) {}
template <class In>
PartNestingGuard<In>::PartNestingGuard(ParserPart& part, RoomChecked room) : guard_(part.in_.reader_, room) {}
template <class In>
PartRawOperatorLook<In>::PartRawOperatorLook(ParserPart& part, bool raw) : look_(part.in_.reader_, raw) {}

inline Token ParserPart::next() { return in_.reader_.next(); }
inline const Token& ParserPart::peek() { return in_.reader_.peek(); }
inline void ParserPart::unget(const Token& t) { in_.reader_.unget(t); }
inline Token ParserPart::expect(std::string_view symbol, std::string_view context) {
  return in_.reader_.expect(symbol, context);
}
inline bool ParserPart::accept(std::string_view symbol) { return in_.reader_.accept(symbol); }
inline const Value* ParserPart::lookup(const Token& t) const { return in_.reader_.lookup(t); }
inline const Token& ParserPart::peek_raw() { return in_.reader_.peek_raw(); }
inline bool ParserPart::reserved(const Token& t) const { return in_.reader_.reserved(t); }
inline const LexedToken* ParserPart::plain_ahead() { return in_.reader_.plain_ahead(); }
inline void ParserPart::consume_plain() { in_.reader_.consume_plain(); }
inline bool ParserPart::plain_symbol(const LexedToken* k, char c) const { return in_.reader_.plain_symbol(k, c); }
inline void ParserPart::skip_expected(char symbol, std::string_view context) {
  in_.reader_.skip_expected(symbol, context);
}
inline std::string ParserPart::expect_identifier_raw(std::string_view context) {
  return in_.reader_.expect_identifier_raw(context);
}
inline auto ParserPart::raw_ahead() { return in_.reader_.raw_ahead(); }
inline void ParserPart::skip_ahead() { in_.reader_.skip_ahead(); }
inline const LexedToken& ParserPart::lexed(FileTokens& tokens, std::size_t index) {
  return in_.reader_.lexed(tokens, index);
}
inline std::string_view ParserPart::text_of(const LexedToken& k) const { return in_.reader_.text_of(k); }
inline Token ParserPart::raw() { return in_.reader_.raw(); }
inline bool ParserPart::ahead_is(std::string_view symbol) { return in_.reader_.ahead_is(symbol); }
inline Token ParserPart::pop_pushed_back() { return in_.reader_.pop_pushed_back(); }

inline void ParserPart::fail(const SourceLoc& loc, const std::string& message) const {
  in_.diagnostics_.fail(loc, message);
}
inline void ParserPart::fail_at(const Token& t, const std::string& message) const {
  in_.diagnostics_.fail_at(t, message);
}
inline void ParserPart::fail_expected(const Token& t, std::string_view expected) const {
  in_.diagnostics_.fail_expected(t, expected);
}
inline void ParserPart::fail_unsupported(const Token& t, std::string_view what) const {
  in_.diagnostics_.fail_unsupported(t, what);
}
inline void ParserPart::warn(const SourceLoc& loc, const std::string& message) const {
  in_.diagnostics_.warn(loc, message);
}

inline Numeric ParserPart::parse_expression() { return in_.expressions().parse_expression(); }
inline Numeric ParserPart::parse_additive() { return in_.expressions().parse_additive(); }
inline Numeric ParserPart::parse_additive_after(Numeric first_operand) {
  return in_.expressions().parse_additive_after(std::move(first_operand));
}
inline bool ParserPart::starts_string(const Token& t) const { return in_.expressions().starts_string(t); }
inline double ParserPart::parse_float() { return in_.expressions().parse_float(); }
inline double ParserPart::parse_float_full() { return in_.expressions().parse_float_full(); }
inline Vec3 ParserPart::parse_vector() { return in_.expressions().parse_vector(); }
inline Colour ParserPart::parse_colour() { return in_.expressions().parse_colour(); }
inline bool ParserPart::starts_colour(const Token& t) const { return in_.expressions().starts_colour(t); }
inline std::string ParserPart::parse_string() { return in_.expressions().parse_string(); }
inline double ParserPart::optional_float(double fallback) { return in_.expressions().optional_float(fallback); }
inline std::pair<double, double> ParserPart::parse_uv_vector(std::string_view context) {
  return in_.expressions().parse_uv_vector(context);
}
inline std::shared_ptr<const FunctionValue> ParserPart::parse_function_definition(const Token& keyword) {
  return in_.functions_.parse_definition(keyword);
}
inline std::uint64_t* ParserPart::function_budget() { return in_.functions_.budget(); }
inline std::optional<Value> ParserPart::try_parse_rvalue(const Token& first) {
  return in_.values_.try_parse_rvalue(first);
}
inline bool ParserPart::nesting_room() const { return in_.reader_.nesting_room(); }
inline int ParserPart::nesting() const { return in_.reader_.nesting(); }
inline TokenStream& ParserPart::token_stream() const { return in_.reader_.stream(); }
inline const SymbolTable& ParserPart::symbol_table() const { return in_.symbols_; }

inline std::optional<SceneItem> ParserPart::try_parse_item(const Token& t) { return in_.objects_.try_parse_item(t); }
inline void ParserPart::parse_object_modifiers(Object& object) { in_.objects_.parse_object_modifiers(object); }
inline void ParserPart::apply_transform(Object& object, const Matrix& m, TransformKind kind) {
  in_.objects_.apply_transform(object, m, kind);
}
inline const NotesPool& ParserPart::notes_pool() const { return in_.notes_pool_; }
inline ObjectExtents ParserPart::extents() const { return in_.extents(); }

inline UnsupportedFeature ParserPart::skip_unsupported(const Token& keyword, const std::string& what) {
  return in_.unsupported_.skip_unsupported(keyword, what);
}
inline void ParserPart::skip_balanced(const Token& open) { in_.unsupported_.skip_balanced(open); }
inline void ParserPart::refuse_if_unsupported(const Unsupported& u, const SourceLoc& placed_at,
                                              std::string_view what) const {
  in_.unsupported_.refuse_if_unsupported(u, placed_at, what);
}
inline void ParserPart::taint(Unsupported& slot, const Unsupported& feature) {
  UnsupportedFeatures::taint(slot, feature);
}

inline std::optional<double> ParserPart::parse_radiosity_importance(const Token& keyword) {
  return in_.radiosity_.parse_importance(keyword);
}

inline const Texture& ParserPart::default_texture() const { return in_.statements_.default_texture(); }
inline int ParserPart::language_version() const { return in_.statements_.language_version(); }
inline bool ParserPart::version_directive_seen() const { return in_.statements_.version_directive_seen(); }
inline const std::optional<double>& ParserPart::assumed_gamma() const { return in_.statements_.assumed_gamma(); }
inline const std::vector<std::filesystem::path>& ParserPart::library_paths() const {
  return in_.options_.library_paths;
}
inline bool ParserPart::povray_tolerances() const { return in_.options_.povray_tolerances; }
inline int ParserPart::noise_generator() const { return in_.statements_.noise_generator(); }
inline void ParserPart::place_object(Object&& object, const SourceLoc& at) {
  in_.statements_.place_object(std::move(object), at);
}
inline void ParserPart::place_light(Light light, const SourceLoc& at) {
  in_.statements_.place_light(std::move(light), at);
}

// ---- the ExpressionParser's (expression_parser.hpp): the Interpreter is the class it is the base of ----
// Empty, so that the base shares the Interpreter's address with the reader and in() costs nothing.
static_assert(std::is_empty_v<ExpressionParser>, "the grammar's state is the Interpreter's");
inline Interpreter& ExpressionParser::in() { return static_cast<Interpreter&>(*this); }
inline const Interpreter& ExpressionParser::in() const { return static_cast<const Interpreter&>(*this); }
inline TokenReader& ExpressionParser::reader() { return in().reader_; }
inline const TokenReader& ExpressionParser::reader() const { return in().reader_; }
inline ExpressionParser::NestingGuard::NestingGuard(ExpressionParser& part, const Token& at)
    : TokenReader::NestingGuard(part.reader(), at) {}
inline ExpressionParser::NestingGuard::NestingGuard(ExpressionParser& part, RoomChecked room)
    : TokenReader::NestingGuard(part.reader(), room) {}

inline Token ExpressionParser::next() { return reader().next(); }
inline const Token& ExpressionParser::peek() { return reader().peek(); }
inline void ExpressionParser::unget(const Token& t) { reader().unget(t); }
inline Token ExpressionParser::expect(std::string_view symbol, std::string_view context) {
  return reader().expect(symbol, context);
}
inline bool ExpressionParser::accept(std::string_view symbol) { return reader().accept(symbol); }
inline const Value* ExpressionParser::lookup(const Token& t) const { return reader().lookup(t); }
inline const Token& ExpressionParser::peek_raw() { return reader().peek_raw(); }
inline bool ExpressionParser::reserved(const Token& t) const { return reader().reserved(t); }
inline Token ExpressionParser::raw() { return reader().raw(); }
inline const LexedToken* ExpressionParser::plain_ahead() { return reader().plain_ahead(); }
inline void ExpressionParser::consume_plain() { reader().consume_plain(); }
inline bool ExpressionParser::plain_symbol(const LexedToken* k, char c) const { return reader().plain_symbol(k, c); }
inline void ExpressionParser::skip_expected(char symbol, std::string_view context) {
  reader().skip_expected(symbol, context);
}
inline TokenReader::Ahead ExpressionParser::raw_ahead() { return reader().raw_ahead(); }
inline void ExpressionParser::skip_ahead() { reader().skip_ahead(); }
inline bool ExpressionParser::nesting_room() const { return reader().nesting_room(); }
inline int ExpressionParser::nesting() const { return reader().nesting(); }
inline TokenStream& ExpressionParser::token_stream() { return reader().stream(); }
inline const TokenStream& ExpressionParser::token_stream() const { return reader().stream(); }
inline const SymbolTable& ExpressionParser::symbol_table() const { return in().symbols_; }
inline void ExpressionParser::fail(const SourceLoc& loc, const std::string& message) const {
  in().diagnostics_.fail(loc, message);
}
inline void ExpressionParser::fail_at(const Token& t, const std::string& message) const {
  in().diagnostics_.fail_at(t, message);
}
inline void ExpressionParser::fail_expected(const Token& t, std::string_view expected) const {
  in().diagnostics_.fail_expected(t, expected);
}
inline void ExpressionParser::fail_unsupported(const Token& t, std::string_view what) const {
  in().diagnostics_.fail_unsupported(t, what);
}
inline void ExpressionParser::warn(const SourceLoc& loc, const std::string& message) const {
  in().diagnostics_.warn(loc, message);
}
inline void ExpressionParser::refuse_if_unsupported(const Unsupported& u, const SourceLoc& placed_at,
                                                    std::string_view what) const {
  in().unsupported_.refuse_if_unsupported(u, placed_at, what);
}
inline int ExpressionParser::language_version() const { return in().statements_.language_version(); }
inline const ParseOptions& ExpressionParser::parse_options() const { return in().options_; }
inline const std::optional<double>& ExpressionParser::assumed_gamma() const {
  return in().statements_.assumed_gamma();
}

}  // namespace povtrace::sdl

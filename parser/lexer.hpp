// Lexical level of POV-Ray SDL (povray-sdl-and-geometry.md §2), written as a PEGTL grammar. The lexer is
// re-entrant: it reads one token at any byte position of a file, which is what macro calls, loops and
// #include need (they replay or switch source positions between any two tokens, §1).
#pragma once

#include <cstddef>
#include <memory>
#include <string_view>

#include "parser/source.hpp"

namespace povtrace::sdl {

enum class TokenKind { end_of_input, number, string, identifier, symbol };

struct TokenValue;   // values.hpp

// Where the lexer stands in one file: byte offset plus the line and column of that byte (both 1-based).
struct LexPosition {
  std::size_t offset = 0;
  int line = 1;
  int column = 1;
};

struct Token {
  TokenKind kind = TokenKind::end_of_input;
  std::string_view text;   // points into the SourceFile's text; strings keep their quotes
  double number = 0;       // value of a number token
  SourceLoc loc;
  LexPosition begin;       // position of the token's first byte
  LexPosition end;         // position just after the token
  // Set by the interpreter's token stream: `processed` once directives, macro calls, array subscripts and
  // deprecation warnings have been dealt with (a token put back and read again is not processed twice);
  // `element` when the token is an array element `A[i]…` (text then spans the whole reference if it lies in one
  // file), holding the element's value.
  bool processed = false;
  std::shared_ptr<const TokenValue> element;

  bool is(std::string_view symbol_or_word) const {
    // Length and first character before the full comparison: most words asked about differ there, and the
    // parser asks a token about many words (a call of memcmp each was 7% of the parse of a #while loop).
    return (kind == TokenKind::symbol || kind == TokenKind::identifier) && text.size() == symbol_or_word.size() &&
           (text.empty() || text[0] == symbol_or_word[0]) && text == symbol_or_word;
  }
};

// Skips white space and comments from `at`, then reads one token. Throws ParseError for an unterminated
// comment or string, a malformed number or an illegal character.
Token lex_token(const SourceFile& file, LexPosition at);

// The decoded contents of a string token (escapes per §2: \a \b \f \n \r \t \v \\ \' \" \uXXXX).
// `decode_escapes` is false for file names (#include), which POV-Ray takes verbatim.
std::string string_value(const Token& token, const SourceFile& file, bool decode_escapes);

}  // namespace povtrace::sdl

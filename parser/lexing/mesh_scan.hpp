// Reading a mesh's literal items straight from the source text, without the token stream (meshes.cpp, mesh2.cpp).
//
// Why: the token stream keeps every token of a file for replay (16 bytes each, 8 more per number), which for a
// million-triangle `mesh {}` is 26 million tokens, 490 MB, and for a mesh2 of the same size 230 MB — several
// times the mesh itself. Items written as plain literals (`triangle { <1, 2, 3>, <4, 5, 6>, <7, 8, 9> }`,
// `<1, 2, 3>,` in a mesh2 section) can never be replayed differently, so they are read here and only their
// values are kept. Anything else — an identifier, an expression, a comment, a directive, an unusual character —
// makes the scanner give up at the start of that item, and the interpreter reads it the ordinary way; values
// read here are the ones the ordinary reading gives (the same number syntax and from_chars, a leading '-' applied
// as parse_unary applies it), so the two readings cannot differ.
#pragma once

#include <array>
#include <charconv>
#include <cstdint>
#include <string_view>

#include "parser/lexing/lexer.hpp"

namespace povtrace::sdl {

class LiteralScanner {
 public:
  LiteralScanner(const SourceFile& file, LexPosition at)
      : base_(file.text.data()), end_(file.text.data() + file.text.size()), at_(at) {}

  // Where the scan stands (line and column counted as the lexer counts them: a byte is a column) and how many
  // tokens the ordinary reading would have read up to here.
  const LexPosition& position() const { return at_; }
  std::uint64_t tokens() const { return tokens_; }
  // Back to an earlier position (the start of an item that did not scan), with its token count.
  void reset(const LexPosition& at, std::uint64_t tokens) {
    at_ = at;
    tokens_ = tokens;
  }

  // The next byte after blanks ('\0' at the end of the text), without reading it.
  char ahead() {
    skip_blanks();
    return at_.offset < size() ? base_[at_.offset] : '\0';
  }
  // A one-byte symbol token. A '<' or '>' followed by '=' is another token ("<=", ">="): no match.
  bool symbol(char c) {
    if (ahead() != c) return false;
    if ((c == '<' || c == '>') && at_.offset + 1 < size() && base_[at_.offset + 1] == '=') return false;
    advance(1);
    ++tokens_;
    return true;
  }
  bool optional_comma() { return symbol(','); }
  // A keyword: the identifier `word`, not the start of a longer identifier.
  bool word(std::string_view w) {
    if (ahead() == '\0' || size() - at_.offset < w.size() || std::string_view(base_ + at_.offset, w.size()) != w)
      return false;
    if (at_.offset + w.size() < size() && identifier_byte(base_[at_.offset + w.size()])) return false;
    advance(w.size());
    ++tokens_;
    return true;
  }
  // `<n1, …, nN>` of literal numbers (each may carry one leading '-'), followed by nothing that would make it
  // part of a larger expression: the next byte must be ',', '<' or '}' (the additive level stops there).
  template <std::size_t N>
  bool vector(std::array<double, N>& out) {
    if (!symbol('<')) return false;
    for (std::size_t k = 0; k < N; ++k) {
      if (!number(out[k])) return false;
      if (!symbol(k + 1 < N ? ',' : '>')) return false;
    }
    const char next = ahead();
    return next == ',' || next == '<' || next == '}';
  }

 private:
  std::size_t size() const { return static_cast<std::size_t>(end_ - base_); }
  static bool digit(char c) { return c >= '0' && c <= '9'; }
  static bool identifier_byte(char c) {
    return digit(c) || (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || c == '_';
  }
  void advance(std::size_t n) {
    at_.offset += n;
    at_.column += static_cast<int>(n);
  }
  // Only the common blanks; any other byte (a comment's '/', '#', a form feed) ends the scan where it stands.
  void skip_blanks() {
    while (at_.offset < size()) {
      const char c = base_[at_.offset];
      if (c == '\n') {
        ++at_.offset;
        ++at_.line;
        at_.column = 1;
      } else if (c == ' ' || c == '\t' || c == '\r') {
        advance(1);
      } else {
        return;
      }
    }
  }
  // [-] number, with the lexer's number syntax (number_end). The byte after it must not continue it ('.', a
  // letter, a digit, '_'): the lexer would read something else there.
  bool number(double& out) {
    const bool negative = symbol('-');
    skip_blanks();
    const char* c = base_ + at_.offset;
    const char* p = number_end(c, end_);
    if (p == c) return false;
    if (p < end_ && (*p == '.' || identifier_byte(*p))) return false;
    const auto [ptr, ec] = std::from_chars(c, p, out);
    if (ec != std::errc() || ptr != p) return false;
    if (negative) out = -out;
    advance(static_cast<std::size_t>(p - c));
    ++tokens_;
    return true;
  }

  const char* base_;
  const char* end_;
  LexPosition at_;
  std::uint64_t tokens_ = 0;
};

}  // namespace povtrace::sdl

// Lexical level of POV-Ray SDL (povray-sdl-and-geometry.md §2), written as a PEGTL grammar. The lexer is
// re-entrant: it reads one token at any byte position of a file, which is what macro calls, loops and
// #include need (they replay or switch source positions between any two tokens, §1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <memory>
#include <string_view>
#include <vector>

#include "scene/source.hpp"

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
  // The identifier's interned name (SymbolTable::NameId), set by the interpreter's token stream so that a lookup
  // indexes instead of hashing the text; 0 for tokens made elsewhere (the text is looked up then).
  std::uint32_t name = 0;
  std::shared_ptr<const TokenValue> element;

  bool is(std::string_view symbol_or_word) const {
    // Length and first character before the full comparison: most words asked about differ there, and the
    // parser asks a token about many words (a call of memcmp each was 7% of the parse of a #while loop).
    return (kind == TokenKind::symbol || kind == TokenKind::identifier) && text.size() == symbol_or_word.size() &&
           (text.empty() || text[0] == symbol_or_word[0]) && text == symbol_or_word;
  }
};

// A token as the interpreter keeps it for replay (Token is built from it when read): 16 bytes, because every
// token of every file read is kept (a 7 MB scene is two million tokens). The column comes from the start of its
// line (FileTokens), a number's value from a side table.
struct LexedToken {
  std::uint32_t offset = 0;        // of the first byte
  std::int32_t line = 1;
  std::uint32_t kind_length = 0;   // TokenKind in the low 3 bits, the length in bytes above
  std::uint32_t payload = 0;       // an identifier's NameId, a number's index in FileTokens' numbers

  TokenKind kind() const { return static_cast<TokenKind>(kind_length & 7u); }
  std::uint32_t length() const { return kind_length >> 3; }
  static constexpr std::uint32_t kMaxLength = UINT32_MAX >> 3;
};

// The tokens of one file in the order they come, lexed when the stream first reaches them and then kept, so that
// loops and macro bodies replay them by index. Stored in fixed chunks: growing never copies (or doubles) them.
class FileTokens {
 public:
  explicit FileTokens(const SourceFile& file) : file_(&file) {}
  const SourceFile& file() const { return *file_; }
  std::size_t size() const { return size_; }
  const LexedToken& operator[](std::size_t i) const { return chunks_[i >> kChunkBits][i & kChunkMask]; }
  // Keeps a lexed token (its length at most LexedToken::kMaxLength, its offset below 4 GB).
  void push_back(const Token& t, std::uint32_t name) {
    push_back(t.kind, t.begin, static_cast<std::uint32_t>(t.text.size()), name, t.number);
  }
  void push_back(TokenKind kind, const LexPosition& begin, std::uint32_t length, std::uint32_t name, double number) {
    append(kind, static_cast<std::uint32_t>(begin.offset), begin.line,
           static_cast<std::uint32_t>(begin.offset) - static_cast<std::uint32_t>(begin.column - 1), length, name,
           number);
  }
  // Reads the common tokens lex_quick reads from `lexed_to` on, keeping them, until `until` tokens are kept or the
  // next token is one lex_quick leaves to lex_token (which the caller then reads); identifiers get their names from
  // `names`. Returns how many it kept. The first reading of a large scene: one loop, no Token, no QuickToken.
  struct NameInterner {
    // What intern() needs of the name, computed ahead (prepare() is called for the identifiers of a run before
    // intern() is called for any of them).
    virtual std::uint64_t prepare(std::string_view name) = 0;
    virtual std::uint32_t intern(std::string_view name, std::uint64_t prepared) = 0;

   protected:
    ~NameInterner() = default;
  };
  std::size_t lex_quick_run(std::size_t until, NameInterner& names);
  // Drops the tokens from `index` on, lexed ahead and read by nobody yet: lexing goes on from the first byte of
  // token `index`, and reads the same tokens again (the mesh literal scanner reads that text itself instead).
  void forget_from(std::size_t index) {
    const LexedToken& k = (*this)[index];
    lexed_to = LexPosition{k.offset, k.line, column(k)};
    for (std::size_t i = index; i < size_; ++i)
      if ((*this)[i].kind() == TokenKind::number) {
        numbers_.resize((*this)[i].payload);
        break;
      }
    size_ = index;
  }
  double number(const LexedToken& k) const { return numbers_[k.payload]; }
  int column(const LexedToken& k) const {
    return static_cast<int>(k.offset - line_starts_[static_cast<std::size_t>(k.line)]) + 1;
  }
  LexPosition lexed_to;   // where lexing goes on (just after the last token kept)

  // Frees the chunks wholly below `index` and below every position a macro body starts at (keep_from): the
  // interpreter's call between statements of the main file, where no loop or macro can return to them. A 7 MB scene
  // of #declares is two million tokens, kept until the end otherwise. Reading a freed token is a bug.
  void release_before(std::size_t index) {
    const std::size_t limit = (index < keep_from_ ? index : keep_from_) >> kChunkBits;
    for (; released_ < limit && released_ < chunks_.size(); ++released_) {
      chunks_[released_].reset();
      if (released_ < notes_.size()) notes_[released_].reset();
    }
  }
  // Token `index` may be read again (a macro body starts there): it and what follows are never freed.
  void keep_from(std::size_t index) {
    if (index < keep_from_) keep_from_ = index;
  }

  // A number the interpreter keeps for token i and a level (0 or 1): what it found out about the expression that
  // starts there (0 until it says). Stored in chunks made only where it writes one: loops are a few lines.
  std::uint32_t note(std::size_t i, unsigned level) const {
    const std::size_t c = i >> kChunkBits;
    return c < notes_.size() && notes_[c] ? notes_[c][(i & kChunkMask) * 2 + level] : 0;
  }
  void set_note(std::size_t i, unsigned level, std::uint32_t value) {
    const std::size_t c = i >> kChunkBits;
    if (notes_.size() <= c) notes_.resize(c + 1);
    if (!notes_[c]) notes_[c] = std::make_unique<std::uint32_t[]>(2 * kChunkSize);   // zeroed
    notes_[c][(i & kChunkMask) * 2 + level] = value;
  }

 private:
  void append(TokenKind kind, std::uint32_t offset, int line, std::uint32_t line_start, std::uint32_t length,
              std::uint32_t name, double number) {
    if ((size_ >> kChunkBits) == chunks_.size()) chunks_.push_back(std::make_unique<LexedToken[]>(kChunkSize));
    LexedToken& k = chunks_[size_ >> kChunkBits][size_ & kChunkMask];
    k.offset = offset;
    k.line = line;
    k.kind_length = length << 3 | static_cast<std::uint32_t>(kind);
    k.payload = name;
    if (kind == TokenKind::number) {
      k.payload = static_cast<std::uint32_t>(numbers_.size());
      numbers_.push_back(number);
    }
    const auto l = static_cast<std::size_t>(line);
    if (line_starts_.size() <= l) line_starts_.resize(l + 1, 0);
    line_starts_[l] = line_start;
    ++size_;
  }
  static constexpr unsigned kChunkBits = 12;
  static constexpr std::size_t kChunkSize = std::size_t{1} << kChunkBits;
  static constexpr std::size_t kChunkMask = kChunkSize - 1;
  const SourceFile* file_;
  std::vector<std::unique_ptr<LexedToken[]>> chunks_;
  std::size_t size_ = 0;
  std::vector<double> numbers_;
  std::vector<std::uint32_t> line_starts_;   // by line: offset of its first byte (lines with tokens only)
  std::vector<std::unique_ptr<std::uint32_t[]>> notes_;
  std::size_t released_ = 0;           // chunks freed, from the first
  std::size_t keep_from_ = SIZE_MAX;   // the lowest index a macro body starts at
};

// Skips white space and comments from `at`, then reads one token. Throws ParseError for an unterminated
// comment or string, a malformed number or an illegal character.
Token lex_token(const SourceFile& file, LexPosition at);

// A token read by lex_quick: its kind, where it starts and how many bytes it has (it lies on one line), and a
// number's value.
struct QuickToken {
  TokenKind kind = TokenKind::end_of_input;
  LexPosition begin;
  std::size_t length = 0;
  double number = 0;
};

// The common tokens read by hand, as lex_token would read them but without building a Token or running the
// grammar: an identifier, a number or a symbol after blanks (the first reading of a large scene is millions of
// them). False, having read nothing, where anything else comes first — a comment, a string, the end of the file,
// a number from_chars does not read exactly, an error — which lex_token then reads.
bool lex_quick(const SourceFile& file, LexPosition at, QuickToken& out);

// grammar::number from `c` (digits [. digits] | . digits, then an optional exponent): the end of the longest
// match before `end`, or `c` where there is none.
const char* number_end(const char* c, const char* end);

// The decoded contents of a string token (escapes per §2: \a \b \f \n \r \t \v \\ \' \" \uXXXX).
// `decode_escapes` is false for file names (#include), which POV-Ray takes verbatim.
std::string string_value(const Token& token, const SourceFile& file, bool decode_escapes);

}  // namespace povtrace::sdl

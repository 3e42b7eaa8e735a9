#include "parser/lexing/lexer.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <cmath>
#include <string>

#include <tao/pegtl.hpp>

namespace povtrace::sdl {
namespace pegtl = tao::pegtl;

// ---- Grammar: one rule per lexical concept -------------------------------------------------------------
namespace grammar {
using namespace pegtl;

// Blanks: isspace characters, plus NUL and Ctrl-Z, which POV-Ray also ignores.
struct blank_char : one<' ', '\t', '\n', '\r', '\v', '\f', '\0', '\x1a'> {};
struct line_comment : seq<two<'/'>, until<eolf>> {};
// Block comments nest (Parse_C_Comments recurses on an inner "/*"; "*/" is tested first). Matched with a depth
// counter rather than a recursive rule, so that deeply nested comments cannot overflow the stack.
inline constexpr const char* kUnterminatedComment =
    "unterminated block comment: expected '*/' before the end of the file (block comments nest, so every '/*' "
    "needs its own '*/')";
struct block_comment {
  using rule_t = block_comment;
  using subs_t = empty_list;
  template <typename ParseInput> static bool match(ParseInput& in) {
    auto next_is = [&in](char a, char b) { return in.size(2) >= 2 && in.peek_char(0) == a && in.peek_char(1) == b; };
    if (!next_is('/', '*')) return false;
    in.bump(2);
    for (int depth = 1; depth > 0;) {
      if (in.size(2) < 2) throw parse_error(kUnterminatedComment, in);
      if (next_is('*', '/')) { in.bump(2); --depth; }
      else if (next_is('/', '*')) { in.bump(2); ++depth; }
      else in.bump(1);
    }
    return true;
  }
};
struct skip : star<sor<plus<blank_char>, line_comment, block_comment>> {};

struct exponent : seq<one<'e', 'E'>, opt<one<'+', '-'>>, plus<digit>> {};
struct number : sor<seq<plus<digit>, opt<one<'.'>, star<digit>>, opt<exponent>>,
                    seq<one<'.'>, plus<digit>, opt<exponent>>> {};
struct identifier : pegtl::identifier {};
// A string may span lines, as in POV-Ray (a literal line break is part of the string).
struct string_char : sor<seq<one<'\\'>, any>, not_one<'"'>> {};
struct string_literal : if_must<one<'"'>, until<one<'"'>, string_char>> {};
struct two_char_symbol : sor<string<'<', '='>, string<'>', '='>, string<'!', '='>> {};
struct one_char_symbol : one<'{', '}', '(', ')', '[', ']', '<', '>', ',', ';', ':', '?', '!', '=', '+', '-', '*',
                             '/', '.', '&', '|', '#', '%', '^', '@', '$', '\'', '~', '`', '\\'> {};
struct symbol : sor<two_char_symbol, one_char_symbol> {};
struct token : sor<number, identifier, string_literal, symbol> {};
struct next_token : seq<skip, sor<eof, token>> {};

template <typename Rule> inline constexpr const char* error_message = nullptr;
template <> inline constexpr const char* error_message<until<one<'"'>, string_char>> =
    "unterminated string: expected '\"' before the end of the file";
struct error_control {
  template <typename Rule> static constexpr auto message = error_message<Rule>;
  template <typename Rule> static constexpr auto raise_on_failure = false;
};
template <typename Rule> using control = must_if<error_control>::control<Rule>;
}  // namespace grammar

// ---- Actions: remember which kind of token matched --------------------------------------------------------
namespace {
struct Capture {
  TokenKind kind = TokenKind::end_of_input;
  const char* begin = nullptr;
  const char* end = nullptr;
};

template <typename Rule> struct action : pegtl::nothing<Rule> {};
template <TokenKind K> struct mark {
  template <typename ActionInput> static void apply(const ActionInput& in, Capture& c) {
    c.kind = K;
    c.begin = in.begin();
    c.end = in.end();
  }
};
template <> struct action<grammar::number> : mark<TokenKind::number> {};
template <> struct action<grammar::identifier> : mark<TokenKind::identifier> {};
template <> struct action<grammar::string_literal> : mark<TokenKind::string> {};
template <> struct action<grammar::symbol> : mark<TokenKind::symbol> {};

LexPosition advance(const LexPosition& start, const char* from, const char* to) {
  LexPosition p = start;
  for (const char* c = from; c < to; ++c) {
    ++p.offset;
    if (*c == '\n') { ++p.line; p.column = 1; } else { ++p.column; }
  }
  return p;
}

SourceLoc loc_of(const SourceFile& file, const LexPosition& p) { return SourceLoc{file.name, p.line, p.column}; }

// The opening '/*' or '"' of the comment or string that runs to the end of the file: blanks, line comments and
// closed block comments are skipped the way the grammar skips them ("*/" is tested before "/*").
const char* unterminated_start(const char* c, const char* end) {
  auto at = [&](const char* p, char a, char b) { return p + 1 < end && p[0] == a && p[1] == b; };
  while (c < end) {
    if (at(c, '/', '/')) {
      while (c < end && *c != '\n') ++c;
    } else if (at(c, '/', '*')) {
      const char* open = c;
      int depth = 0;
      while (c < end) {
        if (at(c, '*', '/')) { c += 2; if (--depth == 0) break; }
        else if (at(c, '/', '*')) { c += 2; ++depth; }
        else ++c;
      }
      if (depth > 0) return open;
    } else if (*c == '"') {
      return c;
    } else {
      ++c;
    }
  }
  return end;
}
}  // namespace

Token lex_token(const SourceFile& file, LexPosition at) {
  const char* base = file.text.data();
  const char* begin = base + at.offset;
  const char* end = base + file.text.size();
  // Lazy tracking and a plain `const char*` source: positions are computed from byte offsets below, so
  // lexing a token allocates nothing (large scenes are millions of tokens).
  pegtl::memory_input<pegtl::tracking_mode::lazy, pegtl::eol::lf_crlf, const char*> in(begin, end, "");
  Capture c;
  bool ok = false;
  try {
    ok = pegtl::parse<grammar::next_token, action, grammar::control>(in, c);
  } catch (const pegtl::parse_error& e) {
    // Report the opening '/*' or '"' that is never closed: the end of the file, where the terminator was
    // expected, does not say which one.
    const SourceLoc loc = loc_of(file, advance(at, begin, unterminated_start(begin, end)));
    throw ParseError(loc, std::string(e.message()), std::string(file.line_text(loc.line)));
  }
  Token t;
  if (!ok) {
    // Not a token and not the end: an illegal character after the skipped blanks. The failed parse rewound
    // the input to `at`, so skip the blanks and comments again to point at the character itself.
    pegtl::parse<grammar::skip>(in);
    const char* bad = in.current();
    LexPosition p = advance(at, begin, bad);
    char hex[8];
    std::snprintf(hex, sizeof hex, "0x%02X", static_cast<unsigned char>(*bad));
    throw ParseError(loc_of(file, p), std::string("illegal character ") + hex + " (expected a number, identifier, "
                     "string, operator or punctuation)", std::string(file.line_text(p.line)));
  }
  if (c.kind == TokenKind::end_of_input) {
    t.begin = t.end = advance(at, begin, end);
    t.loc = loc_of(file, t.begin);
    return t;
  }
  t.kind = c.kind;
  t.text = std::string_view(c.begin, static_cast<std::size_t>(c.end - c.begin));
  t.begin = advance(at, begin, c.begin);
  t.end = advance(t.begin, c.begin, c.end);
  t.loc = loc_of(file, t.begin);
  if (t.kind == TokenKind::number) {
    // A second '.' right after a number is an error in POV-Ray ("1.2.3").
    if (c.end < end && *c.end == '.' && c.end + 1 < end && std::isdigit(static_cast<unsigned char>(c.end[1])))
      throw ParseError(loc_of(file, t.end), "malformed number: a second '.' (expected one decimal point)",
                       std::string(file.line_text(t.end.line)));
    // The grammar has matched the whole number, so from_chars (correctly rounded, like strtod) reads all of it;
    // "1." and "1.e3" are fine.
    const auto [ptr, ec] = std::from_chars(c.begin, c.end, t.number);
    if (ec == std::errc::result_out_of_range) {
      // from_chars leaves the value alone when out of range: underflow reads as 0, overflow is an error.
      t.number = std::strtod(std::string(t.text).c_str(), nullptr);
      if (std::isinf(t.number))
        throw ParseError(t.loc, "number out of range: " + std::string(t.text) + " does not fit in a double",
                         std::string(file.line_text(t.loc.line)));
    }
    (void)ptr;
  }
  return t;
}

namespace {
// The characters of the grammar's rules above, classified once in a table: lex_quick looks at every byte of a
// scene (a chain of comparisons per byte was a third of its time).
enum CharClass : std::uint8_t { kBlank = 1, kDigit = 2, kIdentifierFirst = 4, kIdentifierOther = 8, kSymbol = 16 };
constexpr std::array<std::uint8_t, 256> kCharClasses = [] {
  std::array<std::uint8_t, 256> t{};
  for (const char c : std::string_view(" \t\n\r\v\f\x1a")) t[static_cast<unsigned char>(c)] |= kBlank;
  t[0] |= kBlank;
  for (int c = '0'; c <= '9'; ++c) t[c] |= kDigit | kIdentifierOther;
  for (int c = 'a'; c <= 'z'; ++c) t[c] |= kIdentifierFirst | kIdentifierOther;
  for (int c = 'A'; c <= 'Z'; ++c) t[c] |= kIdentifierFirst | kIdentifierOther;
  t['_'] |= kIdentifierFirst | kIdentifierOther;
  for (const char c : std::string_view("{}()[]<>,;:?!=+-*/.&|#%^@$'~`\\")) t[static_cast<unsigned char>(c)] |= kSymbol;
  return t;
}();
bool has_class(char c, CharClass k) { return (kCharClasses[static_cast<unsigned char>(c)] & k) != 0; }
bool is_blank(char c) { return has_class(c, kBlank); }
bool is_digit(char c) { return has_class(c, kDigit); }
bool is_identifier_first(char c) { return has_class(c, kIdentifierFirst); }
bool is_identifier_other(char c) { return has_class(c, kIdentifierOther); }
bool is_one_char_symbol(char c) { return has_class(c, kSymbol); }

}  // namespace

const char* number_end(const char* c, const char* end) {
  const char* p = c;
  if (p < end && is_digit(*p)) {
    while (p < end && is_digit(*p)) ++p;
    if (p < end && *p == '.')
      for (++p; p < end && is_digit(*p);) ++p;
  } else if (p + 1 < end && *p == '.' && is_digit(p[1])) {
    for (p += 2; p < end && is_digit(*p);) ++p;
  } else {
    return c;
  }
  if (p < end && (*p == 'e' || *p == 'E')) {   // grammar::exponent, optional: without digits it is not part of it
    const char* e = p + 1;
    if (e < end && (*e == '+' || *e == '-')) ++e;
    if (e < end && is_digit(*e)) {
      while (e < end && is_digit(*e)) ++e;
      p = e;
    }
  }
  return p;
}

namespace {
// 10^k for the exact decimal fast path below (every one exactly a double).
constexpr double kExactPowersOfTen[] = {1e0,  1e1,  1e2,  1e3,  1e4,  1e5,  1e6,  1e7,  1e8,  1e9,  1e10, 1e11,
                                        1e12, 1e13, 1e14, 1e15, 1e16, 1e17, 1e18, 1e19, 1e20, 1e21, 1e22};

// One token of lex_quick at `c` (blanks already skipped): its kind and end, and a number's value. False where
// lex_quick leaves the token to lex_token.
bool scan_quick_token(const char* c, const char* end, TokenKind& kind, const char*& token_end, double& number) {
  if (c == end || *c == '"') return false;                                    // the end, a string
  if (*c == '/' && c + 1 < end && (c[1] == '/' || c[1] == '*')) return false;   // a comment
  token_end = number_end(c, end);
  if (token_end != c) {
    kind = TokenKind::number;
    // lex_token's checks: a second '.' is an error, a value from_chars cannot give exactly is handled there.
    if (token_end < end && *token_end == '.' && token_end + 1 < end && is_digit(token_end[1])) return false;
    // Digits with at most one '.', as most numbers of a scene are, at most 15 digits in all: the digits as an
    // integer M (exact, below 2^53) divided by 10^k for k digits after the '.', one correctly rounded division of
    // two exact doubles, so the very double from_chars gives (Clinger's fast path). Digits only were 6% of the
    // first reading of a 7 MB scene through from_chars, decimals like 0.25 another 2%.
    double whole = 0;
    int digits = 0, fraction_digits = -1;
    const char* d = c;
    for (; d < token_end && digits <= 15; ++d) {
      if (*d == '.') {
        if (fraction_digits >= 0) break;
        fraction_digits = 0;
        continue;
      }
      if (!is_digit(*d)) break;
      whole = whole * 10 + (*d - '0');
      ++digits;
      if (fraction_digits >= 0) ++fraction_digits;
    }
    if (d == token_end && digits <= 15) {
      number = fraction_digits > 0 ? whole / kExactPowersOfTen[fraction_digits] : whole;
      return true;
    }
    const auto [ptr, ec] = std::from_chars(c, token_end, number);
    (void)ptr;
    return ec == std::errc();
  }
  if (is_identifier_first(*c)) {
    kind = TokenKind::identifier;
    for (token_end = c + 1; token_end < end && is_identifier_other(*token_end);) ++token_end;
    return true;
  }
  if (c + 1 < end && c[1] == '=' && (*c == '<' || *c == '>' || *c == '!')) {
    kind = TokenKind::symbol;
    token_end = c + 2;
    return true;
  }
  if (is_one_char_symbol(*c)) {
    kind = TokenKind::symbol;
    token_end = c + 1;
    return true;
  }
  return false;   // an illegal character: lex_token reports it
}
}  // namespace

bool lex_quick(const SourceFile& file, LexPosition at, QuickToken& out) {
  const char* base = file.text.data();
  const char* end = base + file.text.size();
  const char* c = base + at.offset;
  for (; c < end && is_blank(*c); ++c) {   // the grammar's blanks, counted as advance() counts them
    ++at.offset;
    if (*c == '\n') { ++at.line; at.column = 1; } else { ++at.column; }
  }
  const char* token_end = c;
  TokenKind kind = TokenKind::number;
  double number = 0;
  if (!scan_quick_token(c, end, kind, token_end, number)) return false;
  out.kind = kind;
  out.begin = at;
  out.length = static_cast<std::size_t>(token_end - c);
  out.number = number;
  return true;
}

std::size_t FileTokens::lex_quick_run(std::size_t until, NameInterner& names) {
  const char* base = file_->text.data();
  const char* end = base + file_->text.size();
  // The position as a line and the offset its line starts at: the column is needed only once per token.
  std::size_t offset = lexed_to.offset;
  int line = lexed_to.line;
  std::size_t line_start = offset - static_cast<std::size_t>(lexed_to.column - 1);
  // Tokens are read in groups, their names prepared for the whole group before any is interned.
  struct Read {
    TokenKind kind;
    std::uint32_t begin, length, line_start;
    int line;
    double number;
    std::uint64_t prepared;
  };
  constexpr std::size_t kGroup = 64;
  Read group[kGroup];
  std::size_t count = 0;
  bool more = true;
  while (more && size_ < until) {
    std::size_t n = 0;
    while (n < kGroup && size_ + n < until) {
      const char* c = base + offset;
      int token_line = line;
      std::size_t token_line_start = line_start;
      for (; c < end && is_blank(*c); ++c)
        if (*c == '\n') {
          ++token_line;
          token_line_start = static_cast<std::size_t>(c - base) + 1;
        }
      const char* token_end = c;
      TokenKind kind = TokenKind::number;
      double number = 0;
      // Anything else is left to lex_token, blanks and all.
      if (!scan_quick_token(c, end, kind, token_end, number)) {
        more = false;
        break;
      }
      const auto begin = static_cast<std::size_t>(c - base);
      const auto length = static_cast<std::size_t>(token_end - c);
      if (static_cast<std::uint64_t>(begin) + length > UINT32_MAX || length > LexedToken::kMaxLength) {
        more = false;
        break;
      }
      group[n++] = Read{kind, static_cast<std::uint32_t>(begin), static_cast<std::uint32_t>(length),
                        static_cast<std::uint32_t>(token_line_start), token_line, number, 0};
      offset = begin + length;
      line = token_line;
      line_start = token_line_start;
    }
    for (std::size_t i = 0; i < n; ++i)
      if (group[i].kind == TokenKind::identifier)
        group[i].prepared = names.prepare(std::string_view(base + group[i].begin, group[i].length));
    for (std::size_t i = 0; i < n; ++i) {
      const Read& r = group[i];
      const std::uint32_t name =
          r.kind == TokenKind::identifier ? names.intern(std::string_view(base + r.begin, r.length), r.prepared) : 0;
      append(r.kind, r.begin, r.line, r.line_start, r.length, name, r.number);
    }
    count += n;
  }
  if (count > 0) lexed_to = LexPosition{offset, line, static_cast<int>(offset - line_start) + 1};
  return count;
}

std::string string_value(const Token& token, const SourceFile& file, bool decode_escapes) {
  std::string_view body = token.text.substr(1, token.text.size() - 2);
  std::string out;
  for (std::size_t i = 0; i < body.size(); ++i) {
    char c = body[i];
    if (c != '\\' || i + 1 >= body.size()) { out += c; continue; }
    char e = body[++i];
    if (e == '"') { out += '"'; continue; }  // the lexer-level escape, kept even in file names
    if (!decode_escapes) { out += '\\'; out += e; continue; }
    switch (e) {
      case 'a': out += '\a'; break;
      case 'b': out += '\b'; break;
      case 'f': out += '\f'; break;
      case 'n': out += '\n'; break;
      case 'r': out += '\r'; break;
      case 't': out += '\t'; break;
      case 'v': out += '\v'; break;
      case '\\': out += '\\'; break;
      case '\'': out += '\''; break;
      case 'u': {
        unsigned code = 0;
        auto hex = body.substr(i + 1, 4);
        auto [ptr, ec] = std::from_chars(hex.data(), hex.data() + hex.size(), code, 16);
        if (hex.size() != 4 || ec != std::errc() || ptr != hex.data() + 4) {
          SourceLoc loc = token.loc;
          loc.column += static_cast<int>(i) + 1;
          throw ParseError(loc, "bad \\u escape: expected four hexadecimal digits",
                           std::string(file.line_text(loc.line)));
        }
        if (code < 0x80) out += static_cast<char>(code); else out += ' ';  // non-ASCII → space, as POV-Ray
        i += 4;
        break;
      }
      default: {
        SourceLoc loc = token.loc;
        loc.column += static_cast<int>(i);
        throw ParseError(loc, std::string("unknown escape sequence '\\") + e +
                         "' (expected one of \\a \\b \\f \\n \\r \\t \\v \\\\ \\' \\\" \\uXXXX)",
                         std::string(file.line_text(loc.line)));
      }
    }
  }
  return out;
}

}  // namespace povtrace::sdl

// The token reader (docs/parser-split-plan.md, step S5): every part reads its tokens through it. next() runs the
// directives and macro calls that may stand between any two tokens (povray-sdl-and-geometry.md §1, items 2 and 5)
// and resolves `A[i]` to its element; the look-aheads (peek, peek_raw, raw_ahead, plain_ahead) and the kept-token
// fast paths read without making Tokens where next() would return the frame's next kept token unchanged. Bodies in
// token_stream.cpp, next to TokenStream::raw(), so that the fetcher's calls of raw() stay in one translation unit.
//
// It owns the TokenStream as its first data member and is the Interpreter's first data member: the reader, its
// stream and the Interpreter share one address, so that the hot paths keep no second pointer around their calls
// (measured in S1: 0.4-1.2% more instructions in the parse benchmarks otherwise). It owns the reader's state: the
// NestingGuard level, RawOperatorLook's flag and whether run() is between statements. It reaches the directives
// (run, quick, call_macro, the running macro's #end), the symbols, the arrays (subscripts) and the diagnostics
// through references to them.
//
// Public interface (what the parts call, through ParserPart's forwarders, and the Interpreter):
//   next, peek, peek_raw, unget, expect, accept, skip_expected, expect_identifier_raw, raw_ahead (inline) and
//   skip_ahead, lookup, reserved, nesting_room, RawOperatorLook, NestingGuard; the raw reads raw, ahead_is and
//   pop_pushed_back (#ifdef's name, the look at the end of a #declare); the kept-token view of the fast paths
//   (plain_ahead, consume_plain, plain_symbol, text_of, lexed, make_token); stream(), nesting() and
//   set_between_statements() for the Interpreter, which builds the other parts around the stream.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "parser/directives/symbols.hpp"
#include "parser/lexing/diagnostics.hpp"
#include "parser/lexing/lexer.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/parse_scene.hpp"

namespace povtrace::sdl {

class ArrayValues;
class DirectiveRunner;

class TokenReader {
 public:
  // Only kept here, not used, until the parse starts (the Interpreter builds the other parts after it).
  TokenReader(const ParseOptions& options, SymbolTable& symbols, DirectiveRunner& directives, ArrayValues& arrays,
              const Diagnostics& diagnostics, TokenStream::IncludeExit& include_exit)
      : stream_(options, symbols, include_exit),
        options_(options),
        symbols_(symbols),
        directives_(directives),
        arrays_(arrays),
        diagnostics_(diagnostics) {}
  TokenReader(const TokenReader&) = delete;
  TokenReader& operator=(const TokenReader&) = delete;

  TokenStream& stream() { return stream_; }
  const TokenStream& stream() const { return stream_; }
  using Frame = TokenStream::Frame;

  Token raw() { return stream_.raw(); }   // next token of the frame stack, no directive processing
  const LexedToken& lexed(FileTokens& tokens, std::size_t index) { return stream_.lexed(tokens, index); }
  Token make_token(const FileTokens& tokens, const LexedToken& t) const { return stream_.make_token(tokens, t); }
  bool ahead_is(std::string_view symbol) { return stream_.ahead_is(symbol); }
  bool reserved(const Token& t) const { return sdl::reserved(symbols_, t); }
  Token next();                  // next token after directives and macro calls
  const Token& peek();   // valid until the next token is read
  // The next token *without* running a directive or macro call it may be (POV-Ray's Ok_To_Declare look-ahead
  // at the end of a #declare): a following `#declare`/`#end` must run only after the current one is finished.
  const Token& peek_raw();   // valid until the next token is read
  // Kind and text of what peek_raw() would return, without making a Token of it when the frame's next token is
  // plain (not '#', not the end of a file): the look for an operator after every operand.
  struct Ahead {
    TokenKind kind;
    std::string_view text;
    bool is(std::string_view s) const {
      // Length and first byte first, as Token::is: asked after every operand, mostly of one-byte symbols.
      return (kind == TokenKind::symbol || kind == TokenKind::identifier) && text.size() == s.size() &&
             (text.empty() || text[0] == s[0]) && text == s;
    }
  };
  // Inline for the frame's next plain token (asked after every operand, by every level of the expression grammar);
  // out of line where a token was pushed back, a frame ends or a directive may follow.
  Ahead raw_ahead() {
    if (!stream_.has_pushed_back()) {
      const Frame& f = stream_.frame();
      const LexedToken& k = lexed(*f.tokens, f.index);
      const std::string_view text(f.file->text.data() + k.offset, k.length());
      if (k.kind() != TokenKind::end_of_input && !(text.size() == 1 && text[0] == '#')) return {k.kind(), text};
    }
    return raw_ahead_full();
  }
  // Whether a directive ahead of a complete operand waits until the value is finished (§1 item 6, POV-Ray's
  // Ok_To_Declare off): in the value of a #declare or #local, a macro argument, an array initialiser and the
  // condition of #if/#elseif/#while/#switch/#case/#range — where POV-Ray reads '#' there as a plain token and
  // reports it. Elsewhere (object, pigment, transform arguments, #debug) POV-Ray's Get_Token runs the directive
  // while it looks for an operator: `pigment { M() * 0.5 }` with M's value inside an #if … #end goes on with `* 0.5`
  // after the directives and the macro's #end (advanced/isocacti.pov).
  class RawOperatorLook {
   public:
    explicit RawOperatorLook(TokenReader& in, bool raw = true) : in_(in), saved_(in.raw_operator_look_) {
      in_.raw_operator_look_ = raw;
    }
    ~RawOperatorLook() { in_.raw_operator_look_ = saved_; }
    RawOperatorLook(const RawOperatorLook&) = delete;
    RawOperatorLook& operator=(const RawOperatorLook&) = delete;

   private:
    TokenReader& in_;
    bool saved_;
  };
  // Reading without making Tokens, where next() would return the frame's next kept token unchanged: nothing is
  // pushed back, and that token is neither '#', nor the end of a file, nor an identifier that runs something or
  // resolves to something else when read (a macro call, an array that subscripts may follow, a deprecated name).
  // The kept token then; nullptr where only next() may read on. A look: nothing is run or consumed.
  const LexedToken* plain_ahead();
  // Consumes the token plain_ahead() or raw_ahead() (when not pushed back) just returned: a symbol, counted
  // against the token limit as next() would count it.
  void consume_plain();
  void skip_ahead();   // consumes the symbol raw_ahead() just returned, pushed back or not
  std::string_view text_of(const LexedToken& k) const { return stream_.text_of(k); }
  bool plain_symbol(const LexedToken* k, char c) const { return stream_.plain_symbol(k, c); }
  // expect() where its Token is not needed: a plain `symbol` ahead is consumed without making one.
  void skip_expected(char symbol, std::string_view context);
  bool nesting_room() const;   // whether NestingGuard would let one more level in
  int nesting() const { return nesting_; }   // the levels NestingGuard counts now (the expression programs read it)
  void unget(const Token& t) { stream_.unget(t); }
  Token pop_pushed_back() { return stream_.pop_pushed_back(); }
  Token expect(std::string_view symbol, std::string_view context);
  bool accept(std::string_view symbol);   // consumes the token if it is `symbol`
  std::string expect_identifier_raw(std::string_view context);
  // The value an identifier token stands for: an array element's value (Token::element), else the symbol
  // visible under its name; nullptr for anything else. Every identifier lookup goes through here.
  const Value* lookup(const Token& t) const;
  // True while run() reads the next statement's first token: a directive then run at nesting level 0 stands
  // between statements, where nothing holds a kept token (FileTokens::release_before).
  void set_between_statements(bool between) { between_statements_ = between; }

  class NestingGuard {
   public:
    NestingGuard(TokenReader& in, const Token& at);
    // One more level where nesting_room() has just said there is room: nothing to report, so no Token needed.
    struct RoomChecked {};
    NestingGuard(TokenReader& in, RoomChecked) : in_(in) { ++in_.nesting_; }
    ~NestingGuard() { --in_.nesting_; }
    NestingGuard(const NestingGuard&) = delete;
    NestingGuard& operator=(const NestingGuard&) = delete;

   private:
    TokenReader& in_;
  };

 private:
  // The frames and kept tokens (lexing/token_stream.hpp); the functions above of the same names forward to it. The
  // first data member: see the header comment.
  TokenStream stream_;
  Ahead raw_ahead_full();
  // `#declare`, `#local` and `#end` — the directives loops run — read from the kept tokens, neither the '#' nor
  // the word made a Token unless an error needs it. False, having read nothing, where next() takes the full path:
  // a token limit, a cancel check due, the nesting limit near, another directive, a pushed-back token.
  bool quick_directive();
  // next() on a fresh identifier: the deprecation warning, and `A[i]…` resolved to its element.
  void process_identifier(Token& t, const Value* v);
  [[noreturn]] void fail_at(const Token& t, const std::string& message) const { diagnostics_.fail_at(t, message); }
  [[noreturn]] void fail_expected(const Token& t, std::string_view expected) const {
    diagnostics_.fail_expected(t, expected);
  }
  void warn(const SourceLoc& loc, const std::string& message) const { diagnostics_.warn(loc, message); }

  const ParseOptions& options_;
  SymbolTable& symbols_;
  DirectiveRunner& directives_;
  ArrayValues& arrays_;
  const Diagnostics& diagnostics_;
  bool raw_operator_look_ = false;   // RawOperatorLook's flag
  bool between_statements_ = false;  // set_between_statements()
  int nesting_ = 0;   // the levels NestingGuard counts, up to kMaxNesting (lexing/nesting_limit.hpp)
};

}  // namespace povtrace::sdl

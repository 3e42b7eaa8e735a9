// The directives and macro calls (docs/parser-split-plan.md, step S4): the control stack of the open #if, #switch,
// #while, #for and macro calls, the arguments of the macro calls being read, and the directives themselves.
// Implemented in directives.cpp (#declare … #macro, #version's reading, #debug…), macros.cpp (macro calls and
// their return) and file_io.cpp (#fopen #read #write #fclose).
//
// Public interface, as the token reader (TokenReader, lexing/token_reader.hpp: next(), peek_raw(), raw_ahead_full(),
// quick_directive()) and the other parts use it:
//   run(hash)                    a directive whose '#' next() has just read
//   quick_word(word), quick(…)   the directives loops run (#declare, #local, #end) read from the kept tokens.
//                                The plan had one `bool quick()`; it is split because its look runs for every
//                                token and reads the reader's state (nesting, between statements): the look stays
//                                in TokenReader::quick_directive (token_stream.cpp), which calls quick() only once
//                                it has stepped past a '#' and one of these words.
//   call_macro(name)             a macro call whose name next() has just read (today invoke_macro)
//   running_macro_here(), end(word)  peek_raw()'s exemption of the running macro's #end
//   end_running_macro_ahead()    the same from the kept tokens (raw_ahead_full)
//   leaving_include(frame, file) the end of an include file (TokenStream::IncludeExit; once per file)
//   replaying(), loop_in_frame(frame), none_open(), check_closed_at_end()  queries of the control stack
//   find_include(name)           the include search, which file_exists() asks too
//
// It is a ParserPart (parser_part.hpp): the token reader's, the diagnostics' and the expressions' services come
// through ParserPart's forwarders, as for every part (next, peek, peek_raw, unget, expect, accept, skip_expected,
// expect_identifier_raw, plain_ahead, consume_plain, raw_ahead, skip_ahead, lookup, reserved, fail_at,
// fail_expected, warn, RawOperatorLook, parse_float(_full), parse_additive, parse_expression, parse_string,
// starts_string, try_parse_rvalue, language_version). The services only it uses go through the private inline
// forwarders of directive_services.hpp: to the ArrayValues part (parse_defined_identifier, parse_element_reference,
// store_element, directive_declare_element), to the FunctionValues part (check_function_redeclaration), to the
// ValueReader it holds (numeric_ahead, call_macros_ahead) and to the SceneStatements part (parse_default,
// directive_version). The token stream's kept tokens and frames, the symbols, the diagnostics' fail(loc) and the
// options it holds directly.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "parser/directives/symbols.hpp"
#include "parser/lexing/diagnostics.hpp"
#include "parser/lexing/lexer.hpp"
#include "parser/lexing/token_stream.hpp"
#include "parser/parse_scene.hpp"
#include "parser/parser_part.hpp"

namespace povtrace::sdl {

class Interpreter;
class ValueReader;

class DirectiveRunner final : public TokenStream::IncludeExit, ParserPart {
 public:
  // Only kept here, not used, until a directive runs (the Interpreter builds its parts around it).
  DirectiveRunner(Interpreter& in, const ParseOptions& options, TokenStream& stream, SymbolTable& symbols,
                  const Diagnostics& diagnostics, ValueReader& values)
      : ParserPart(in),
        in_(in),
        values_(values),
        options_(options),
        stream_(stream),
        symbols_(symbols),
        diagnostics_(diagnostics) {}
  DirectiveRunner(const DirectiveRunner&) = delete;
  DirectiveRunner& operator=(const DirectiveRunner&) = delete;

  void run(const Token& hash);   // the directive after `hash` (today Interpreter::directive)
  // `#declare`, `#local` and `#end` — the directives loops run — read from the kept tokens: which of them the word
  // after a '#' is (its payload compared, not its text).
  enum class Quick : std::uint8_t { none, declare, local, end };
  Quick quick_word(const LexedToken& word) const {
    if (word.kind() != TokenKind::identifier) return Quick::none;
    return word.payload == word_declare_ ? Quick::declare
           : word.payload == word_local_ ? Quick::local
           : word.payload == word_end_   ? Quick::end
                                         : Quick::none;
  }
  // Runs that directive, the stream just past its '#' and word (`tokens[word_index]`: the word's kept token, for
  // the Token an #end may need). Inline, below.
  void quick(Quick kind, FileTokens& tokens, std::size_t word_index);
  void call_macro(const Token& name);   // a macro call: its arguments read, its body's frame pushed
  // Whether the innermost open construct is a macro call whose body is the frame read now: its #end returns.
  bool running_macro_here() const {
    return !controls_.empty() && controls_.back().kind == Control::Kind::macro_call &&
           controls_.back().frame == stream_.depth() - 1;
  }
  void end(const Token& at) { directive_end(at); }   // the #end read at `at` (its word)
  // The #end of the running macro, which peek_raw() runs before looking on in the caller, read from the kept
  // tokens: where the frame's next tokens are '#' and `end` of the running macro (counted against the cancel
  // check, as raw() would count them), returns from the macro: true. False, having read nothing, elsewhere and
  // where the cancel check is due.
  bool end_running_macro_ahead() {
    if (!running_macro_here()) return false;
    const TokenStream::Frame& f = stream_.frame();
    if (!stream_.plain_symbol(&stream_.lexed(*f.tokens, f.index), '#')) return false;
    const LexedToken& word = stream_.lexed(*f.tokens, f.index + 1);
    if (word.kind() != TokenKind::identifier || word.payload != word_end_) return false;
    // raw() reads the '#' and the word; where the cancel check is due, it makes it
    if (options_.cancel && !stream_.count_for_cancel_check(2)) return false;
    return_from_macro();   // directive_end of a macro call in its own frame
    return true;
  }
  // The end of an include file for the stream: no directive may stay open in it, and its #local scope closes.
  void leaving_include(std::size_t frame, const SourceFile& file) override;
  // Inside a macro body or a #while/#for loop: where expressions are read again.
  bool replaying() const {
    if (stream_.frame().kind == TokenStream::Frame::Kind::macro) return true;
    for (const Control& c : controls_)
      if (c.kind == Control::Kind::while_loop || c.kind == Control::Kind::for_loop) return true;
    return false;
  }
  // Whether a #while/#for started in `frame` is open (it will go back to earlier tokens of that frame's file).
  bool loop_in_frame(std::size_t frame) const {
    bool found = false;
    for (const Control& c : controls_)
      if ((c.kind == Control::Kind::while_loop || c.kind == Control::Kind::for_loop) && c.frame == frame)
        found = true;
    return found;
  }
  bool none_open() const { return controls_.empty(); }   // no #if, #switch, loop or macro call open
  void check_closed_at_end() const;   // at the end of the main file: an open directive is an error
  std::optional<std::filesystem::path> find_include(const std::string& name) const;

 private:
  using Frame = TokenStream::Frame;
  struct Control {
    enum class Kind { if_branch, while_loop, for_loop, macro_call, switch_block } kind = Kind::if_branch;
    std::size_t frame = 0;       // frame the construct started in (loops must end there)
    TokenStream::Position resume;   // while: start of the condition; for: first token of the body
    std::string for_variable;
    double for_end = 0, for_step = 1;
    double switch_value = 0;     // #switch: the value #case/#range compare with
    SourceLoc loc;
  };

  // ---- directives (directives.cpp) ----
  void directive_declare(bool local);
  void directive_undef();
  void directive_include(const Token& at);
  void directive_if(const Token& at, int kind);   // 0 #if, 1 #ifdef, 2 #ifndef
  void directive_else(const Token& at, bool is_elseif);
  void directive_end(const Token& at);
  void directive_while(const Token& at);
  void directive_for(const Token& at);
  void directive_macro(const Token& at);
  void directive_switch(const Token& at);
  void directive_case(const Token& at, bool is_range);
  void directive_break(const Token& at);
  bool case_matches(const Token& word);   // parses #case (F) / #range (Lo, Hi) against the current #switch
  // A #switch section that did not match: skips to the next #case/#range that matches, an #else (then runs it)
  // or the #end (then leaves the #switch).
  void skip_switch_section(const Token& at);
  void directive_message(const Token& at, const std::string& kind);
  bool condition_in_parens();
  bool identifier_defined_in_parens();
  // Skips raw tokens to the #else/#elseif/#end closing the current level; returns the directive name found
  // ("else", "elseif", "end"), leaving the stream just after that word.
  std::string skip_branch(const Token& opener, bool stop_at_else);
  // An include file's frame and its #local scope, which leaving_include closes.
  void push_file(const std::filesystem::path& path, const Token& at, Frame::Kind kind) {
    stream_.push_file(path, at, kind);
    symbols_.push_scope();
  }
  // ---- macro calls (macros.cpp) ----
  void return_from_macro() {
    stream_.pop_frame();
    symbols_.pop_scope();
    controls_.pop_back();
  }
  // ---- file I/O (file_io.cpp) ----
  // (Not a UserFiles part of its own: it has no state — the open files are symbol values — and reads through the
  // same services as the directives.)
  void directive_fopen(const Token& at);
  void directive_fclose(const Token& at);
  void directive_read(const Token& at);
  void directive_write(const Token& at);
  // The absolute, symlink-resolved path of a user file, refused unless it lies under the scene file's directory or
  // the working directory (symbolic links resolved).
  std::filesystem::path confined_path(const std::string& name, const Token& at) const;

  // ---- the token stream and diagnostics, held directly ----
  Token raw() { return stream_.raw(); }
  const LexedToken& lexed(FileTokens& tokens, std::size_t index) { return stream_.lexed(tokens, index); }
  Token make_token(const FileTokens& tokens, const LexedToken& t) const { return stream_.make_token(tokens, t); }
  bool ahead_is(std::string_view symbol) { return stream_.ahead_is(symbol); }
  bool frame_ahead_is(std::string_view symbol) { return stream_.frame_ahead_is(symbol); }
  std::string_view text_of(const LexedToken& k) const { return stream_.text_of(k); }
  bool plain_symbol(const LexedToken* k, char c) const { return stream_.plain_symbol(k, c); }
  const SourceFile& file_of(const SourceLoc& loc) const { return stream_.file_of(loc); }
  FileName file_name(std::string_view name) { return stream_.file_name(name); }
  [[noreturn]] void fail(const SourceLoc& loc, const std::string& message) const { diagnostics_.fail(loc, message); }

  // ---- the Interpreter's services only the directives use (directive_services.hpp); the reader's and the
  // expressions' come through ParserPart, as for every part ----
  bool numeric_ahead();
  void call_macros_ahead();
  bool parse_defined_identifier();
  auto parse_element_reference(const Token& name);
  void store_element(ArrayValue& a, std::size_t index, Value value, const Token& at, const std::string& name);
  void directive_declare_element(const Token& name, bool local);
  void check_function_redeclaration(const Token& name, bool local, const Value& value);
  void parse_default(const Token& keyword);
  void directive_version(const Token& at);

  // The Interpreter again (ParserPart keeps its own private): for the forwarders above to the parts only the
  // directives call (directive_services.hpp).
  Interpreter& in_;
  // The right-hand values (statements/value_reader.hpp), held here: #declare's numeric path calls it twice per
  // directive, and a reference of its own costs no address computed from the Interpreter's (measured: 4 M of
  // parse_while's 14 M more instructions came from that).
  ValueReader& values_;
  const ParseOptions& options_;
  TokenStream& stream_;
  SymbolTable& symbols_;
  const Diagnostics& diagnostics_;
  std::vector<Control> controls_;
  std::vector<std::pair<SymbolTable::NameId, Value>> macro_arguments_;   // of the macro calls being read
  // The directive words the token stream asks every identifier after a '#' about, as NameIds: a kept token's
  // payload is compared instead of its text.
  const SymbolTable::NameId word_declare_ = symbols_.intern("declare");
  const SymbolTable::NameId word_local_ = symbols_.intern("local");
  const SymbolTable::NameId word_end_ = symbols_.intern("end");
};

// Inline into quick_directive, where its body was (measured: as a call, 1.1% more instructions in parse_while): the
// token reader runs it for every #declare, #local and #end of a loop.
[[gnu::always_inline]] inline void DirectiveRunner::quick(Quick kind, FileTokens& tokens, std::size_t word_index) {
  if (kind == Quick::declare || kind == Quick::local) {
    directive_declare(kind == Quick::local);
    return;
  }
  // #end: the round of a #while loop and the end of an #if without a Token; the rest as directive_end does it.
  if (!controls_.empty()) {
    const Control& c = controls_.back();
    if (c.kind == Control::Kind::if_branch) {
      controls_.pop_back();
      return;
    }
    if (c.kind == Control::Kind::while_loop && stream_.depth() - 1 == c.frame) {
      const Control loop = c;
      stream_.seek(loop.resume);
      if (condition_in_parens()) return;
      controls_.pop_back();
      Token opener = make_token(tokens, tokens[word_index]);
      opener.text = "while";
      skip_branch(opener, false);
      return;
    }
  }
  directive_end(make_token(tokens, tokens[word_index]));
}

}  // namespace povtrace::sdl

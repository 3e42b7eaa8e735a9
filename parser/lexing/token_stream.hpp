// The token stream: the stack of source frames (main file, include files, macro bodies) and the tokens kept for
// each file, read raw — no directive, no macro call, no symbol lookup. Directives and macro calls run above it,
// in the Interpreter's next(), which reads through here (docs/parser-split-plan.md, step S1).
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "parser/directives/symbols.hpp"
#include "parser/lexing/lexer.hpp"
#include "parser/parse_scene.hpp"

namespace povtrace::sdl {

struct MacroDefinition;

class TokenStream {
 public:
  struct Frame {
    const SourceFile* file = nullptr;
    FileTokens* tokens = nullptr;    // the file's tokens; the frame reads tokens[index] next
    std::size_t index = 0;
    enum class Kind { main, include, macro } kind = Kind::main;
    SourceLoc origin;                // the #include or the macro call that opened this frame (error chains)
    std::string_view macro_name;     // points into the calling file's text, which lives as long as the parse
  };
  // The owner's part when raw() reaches the end of an include file: the directives still open in it (an error)
  // and its #local scope. Once per include file read, never on the token path.
  class IncludeExit {
   public:
    virtual void leaving_include(std::size_t frame, const SourceFile& file) = 0;

   protected:
    ~IncludeExit() = default;
  };

  // `symbols` interns the identifiers the lexer keeps. It and `exit` are only kept here, not used, until tokens are
  // read (the Interpreter builds them after the stream).
  TokenStream(const ParseOptions& options, SymbolTable& symbols, IncludeExit& exit)
      : options_(options), symbols_(symbols), exit_(exit) {}
  TokenStream(const TokenStream&) = delete;
  TokenStream& operator=(const TokenStream&) = delete;

  // ---- frames ----
  void open_main(std::unique_ptr<SourceFile> main_file);
  // An include file's frame, refused beyond POV-Ray's depth of nested files.
  void push_file(const std::filesystem::path& path, const Token& at, Frame::Kind kind);
  void push_macro(const MacroDefinition& macro, const Token& name);   // the body of a macro called at `name`
  void pop_frame() { frames_.pop_back(); }
  // The frame read now. Its position changes only through the functions below: step(), jump_to(), seek().
  const Frame& frame() const { return frames_.back(); }
  std::size_t depth() const { return frames_.size(); }   // frames open; the current one is depth() - 1
  std::size_t count(Frame::Kind kind) const;             // frames of that kind open
  const SourceFile& main_file() const { return *frames_.front().file; }

  // ---- positions ----
  // Where the stream reads next: the frame (0 the main file) and its token index. A #while/#for goes back to it
  // for each round.
  struct Position {
    std::size_t frame = 0, index = 0;
  };
  Position position() const { return {frames_.size() - 1, frames_.back().index}; }
  // Back to `p` (a #while/#for round): the frames above its frame closed, nothing pushed back.
  void seek(Position p);
  // The frame's next token, whose tokens from there on are kept for replaying (a macro body: every call reads it
  // again from here).
  struct ReplayPoint {
    const SourceFile* file = nullptr;
    FileTokens* tokens = nullptr;
    std::size_t index = 0;
  };
  ReplayPoint replay_point();
  // Past `n` tokens of the frame read from its kept tokens (plain_ahead(), the words of a quick directive), as
  // raw() would have read them (the token limit and cancel check are the caller's).
  void step(std::size_t n = 1) { frames_.back().index += n; }
  // To the frame's token `index`, just after the kept tokens an expression program read.
  void jump_to(std::size_t index) { frames_.back().index = index; }

  // ---- kept tokens ----
  // Token `index` of a file, lexed on first use (a lexical error is raised when the stream reaches it, as if the
  // file were lexed on the fly). Loops and macro bodies replay kept tokens: no lexing, no lookup per token.
  const LexedToken& lexed(FileTokens& tokens, std::size_t index) {
    return index < tokens.size() ? tokens[index] : lex_more(tokens, index);
  }
  const LexedToken& lex_more(FileTokens& tokens, std::size_t index);
  Token make_token(const FileTokens& tokens, const LexedToken& t) const;
  FileTokens& tokens_of(const SourceFile& file);
  Frame frame_for(const SourceFile& file, std::size_t index, Frame::Kind kind, const SourceLoc& origin,
                  std::string_view macro_name);
  std::string_view text_of(const LexedToken& k) const {
    return std::string_view(frames_.back().file->text.data() + k.offset, k.length());
  }
  bool plain_symbol(const LexedToken* k, char c) const {
    return k && k->kind() == TokenKind::symbol && k->length() == 1 && frames_.back().file->text[k->offset] == c;
  }

  // ---- raw tokens ----
  Token raw();   // next token of the frame stack, no directive processing
  // Whether the next raw token (the one pushed back, else the frame's next) is `symbol`, without reading it:
  // a look that runs no directive and lexes at most that one token.
  bool ahead_is(std::string_view symbol) {
    return pushed_back_.empty() ? frame_ahead_is(symbol) : pushed_back_.back().is(symbol);
  }
  bool frame_ahead_is(std::string_view symbol);   // the frame's next token, whatever was pushed back
  bool has_pushed_back() const { return !pushed_back_.empty(); }
  void unget(const Token& t) { pushed_back_.push_back(t); }
  Token& pushed_back() { return pushed_back_.back(); }   // the token next() reads first
  void drop_pushed_back() { pushed_back_.pop_back(); }
  Token pop_pushed_back() {
    Token t = std::move(pushed_back_.back());
    pushed_back_.pop_back();
    return t;
  }
  // The token pushed back, else raw(): what reads an lvalue after a look-ahead (#declare's name, #read's targets).
  Token raw_or_pushed_back() { return pushed_back_.empty() ? raw() : pop_pushed_back(); }
  // Counts `n` tokens read from the kept tokens, not through raw(), against ParseOptions::cancel's check; false,
  // counting nothing, where the check is due (raw() then makes it).
  bool count_for_cancel_check(std::uint32_t n) {
    if (tokens_until_cancel_check_ < n) return false;
    tokens_until_cancel_check_ -= n;
    return true;
  }

  // ---- literal mesh items (mesh_scan.hpp) ----
  // Literal mesh items read straight from the source text, where the stream's next token is the first of its file
  // not yet lexed (or the one just lexed ahead, `ahead` = 1) and no loop can replay the file there
  // (`loop_in_frame`: a #while/#for of this frame is open); literal_scan_commit() then moves the stream past what
  // the scanner read.
  struct LiteralScanStart {
    LexPosition at;
    std::size_t ahead = 0;
  };
  std::optional<LiteralScanStart> literal_scan_start(bool loop_in_frame);
  void literal_scan_commit(const LiteralScanStart& start, const LexPosition& to, std::uint64_t tokens);
  // The scanner's per-item checks: the token limit, and Ctrl-C every 4096 items; then too, the text read since
  // `scan_begin` is released (SourceFile::release): nothing will read it again.
  bool literal_scan_allows(std::uint64_t tokens, std::size_t items, const LexPosition& at, std::size_t scan_begin);

  // The file names the locations of the parse point to (the SceneDescription keeps them).
  FileName file_name(std::string_view name) { return names_->intern(name); }
  const std::shared_ptr<FileNames>& file_names() const { return names_; }

  // ---- for diagnostics ----
  // How the current position was reached, innermost first ("  in macro M called from f:l:c", "  included from
  // f:l:c"), one line each, for diagnostics; empty in the main file.
  std::string reached_from() const;
  const SourceFile& file_of(const SourceLoc& loc) const;
  // The error `message` at `loc`, with the line it points to and reached_from() (Diagnostics words the messages).
  ParseError error(const SourceLoc& loc, const std::string& message) const;

 private:
  [[noreturn]] void fail(const SourceLoc& loc, const std::string& message) const;

  const ParseOptions& options_;
  SymbolTable& symbols_;
  IncludeExit& exit_;
  std::shared_ptr<FileNames> names_ = std::make_shared<FileNames>();
  std::vector<std::unique_ptr<SourceFile>> files_;
  std::vector<Frame> frames_;
  std::vector<Token> pushed_back_;
  std::uint64_t tokens_read_ = 0;   // against ParseOptions::max_tokens
  std::uint32_t tokens_until_cancel_check_ = 0;   // ParseOptions::cancel is read once every kCancelCheckTokens
  std::vector<std::unique_ptr<FileTokens>> token_stores_;   // one per file read (files_ holds the texts)
};

}  // namespace povtrace::sdl

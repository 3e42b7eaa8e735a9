// The token stream: a stack of source frames (main file, include files, macro bodies), read raw by TokenStream
// (token_stream.hpp). Directives and macro calls are executed here too, by the TokenReader's token fetcher next(),
// so they may stand between any two tokens (povray-sdl-and-geometry.md §1, items 2 and 5). Both share this file
// so that the fetcher's calls of raw() stay in one translation unit.
#include <algorithm>


#include "parser/lexing/token_stream.hpp"

#include "parser/interpreter.hpp"
#include "parser/lexing/nesting_limit.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
constexpr std::size_t kMaxIncludeDepth = 32;    // POV-Ray's limit of nested files
}  // namespace

namespace {
// The symbol table's names for the identifiers the lexer keeps.
struct SymbolNames final : FileTokens::NameInterner {
  explicit SymbolNames(SymbolTable& s) : symbols(s) {}
  std::uint64_t prepare(std::string_view name) override { return symbols.prefetch(name); }
  std::uint32_t intern(std::string_view name, std::uint64_t hash) override { return symbols.intern(name, hash); }
  SymbolTable& symbols;
};
// How far the lexer reads ahead of the token asked for, in one run of lex_quick_run: lexing is context free (the
// grammar's tokens never depend on the parse), and what it cannot read quickly — a comment, a string, an error —
// stops the run, so that lex_token reads it, and reports it, only when the parse reaches it.
constexpr std::size_t kLexAhead = 256;
}  // namespace

const LexedToken& TokenStream::lex_more(FileTokens& tokens, std::size_t index) {
  const SourceFile& file = tokens.file();
  while (tokens.size() <= index) {
    if (tokens.size() > 0 && tokens[tokens.size() - 1].kind() == TokenKind::end_of_input)
      return tokens[tokens.size() - 1];   // the end of a file reads as the end however often it is asked for
    if (SymbolNames names(symbols_); tokens.lex_quick_run(index + kLexAhead, names) > 0) continue;
    if (QuickToken q; lex_quick(file, tokens.lexed_to, q)) {   // most tokens: no grammar run, no Token made
      if (q.begin.offset + q.length > UINT32_MAX || q.length > LexedToken::kMaxLength)
        fail(SourceLoc{file.name, q.begin.line, q.begin.column},
             "the file is larger than 4 GB or has a token longer than 512 MB (the most povtrace reads)");
      const std::string_view text(file.text.data() + q.begin.offset, q.length);
      const auto length = static_cast<std::uint32_t>(q.length);
      tokens.push_back(q.kind, q.begin, length, q.kind == TokenKind::identifier ? symbols_.intern(text) : 0, q.number);
      tokens.lexed_to = LexPosition{q.begin.offset + q.length, q.begin.line, q.begin.column + static_cast<int>(length)};
      continue;
    }
    const Token t = lex_token(file, tokens.lexed_to);   // a lexical error throws before anything is kept
    if (t.end.offset > UINT32_MAX || t.text.size() > LexedToken::kMaxLength)
      fail(t.loc, "the file is larger than 4 GB or has a token longer than 512 MB (the most povtrace reads)");
    tokens.push_back(t, t.kind == TokenKind::identifier ? symbols_.intern(t.text) : 0);
    tokens.lexed_to = t.end;
  }
  return tokens[index];
}

Token TokenStream::make_token(const FileTokens& tokens, const LexedToken& k) const {
  const SourceFile& file = tokens.file();
  const TokenKind kind = k.kind();
  const std::uint32_t length = k.length();
  const int column = tokens.column(k);
  const std::string_view text(file.text.data() + k.offset, length);
  const LexPosition begin{k.offset, k.line, column};
  LexPosition end{k.offset + length, k.line, column + static_cast<int>(length)};
  if (kind == TokenKind::string) {
    // Only a string may span lines: the end is then counted from its last line break, as the lexer counts.
    if (const auto last = text.rfind('\n'); last != std::string_view::npos) {
      end.line += static_cast<int>(std::count(text.begin(), text.end(), '\n'));
      end.column = static_cast<int>(length - last);
    }
  }
  return Token{kind,
               text,
               kind == TokenKind::number ? tokens.number(k) : 0.0,
               SourceLoc{file.name, k.line, column},
               begin,
               end,
               false,
               kind == TokenKind::identifier ? k.payload : 0,
               {}};
}

FileTokens& TokenStream::tokens_of(const SourceFile& file) {
  for (const auto& t : token_stores_)
    if (&t->file() == &file) return *t;
  return *token_stores_.emplace_back(std::make_unique<FileTokens>(file));
}

TokenStream::Frame TokenStream::frame_for(const SourceFile& file, std::size_t index, Frame::Kind kind,
                                          const SourceLoc& origin, std::string_view macro_name) {
  return Frame{&file, &tokens_of(file), index, kind, origin, macro_name};
}

bool TokenStream::frame_ahead_is(std::string_view symbol) {
  Frame& f = frames_.back();
  const LexedToken& k = lexed(*f.tokens, f.index);
  return (k.kind() == TokenKind::symbol || k.kind() == TokenKind::identifier) && k.length() == symbol.size() &&
         std::string_view(f.file->text.data() + k.offset, symbol.size()) == symbol;
}

Token TokenStream::raw() {
  while (true) {
    Frame& f = frames_.back();
    const LexedToken& k = lexed(*f.tokens, f.index);
    if (k.kind() != TokenKind::end_of_input) {
      ++f.index;
      if (options_.max_tokens && ++tokens_read_ > options_.max_tokens)
        fail(make_token(*f.tokens, k).loc, "the parse read more than " + std::to_string(options_.max_tokens) +
                                               " tokens (the token limit of this run)");
      if (options_.cancel && tokens_until_cancel_check_-- == 0) {
        // Every directive of a #while loop passes here, so even a runaway loop reaches this check.
        constexpr std::uint32_t kCancelCheckTokens = 4096;   // an atomic load per 4096 tokens costs nothing
        tokens_until_cancel_check_ = kCancelCheckTokens;
        if (options_.cancel->load(std::memory_order_relaxed))
          fail(make_token(*f.tokens, k).loc, "interrupted while parsing");
      }
      return make_token(*f.tokens, k);
    }
    const Token t = make_token(*f.tokens, k);
    if (f.kind == Frame::Kind::main) return t;
    if (f.kind == Frame::Kind::macro)
      fail(t.loc, "end of file inside a macro body: expected '#end'");
    // End of an include file: its #local variables die with it (§3).
    exit_.leaving_include(frames_.size() - 1, *f.file);
    frames_.pop_back();
  }
}

void TokenStream::open_main(std::unique_ptr<SourceFile> main_file) {
  frames_.push_back(frame_for(*main_file, 0, Frame::Kind::main, {}, {}));
  files_.push_back(std::move(main_file));
}

void TokenStream::push_macro(const MacroDefinition& macro, const Token& name) {
  frames_.push_back(Frame{macro.file, macro.tokens, macro.body, Frame::Kind::macro, name.loc, name.text});
}

std::size_t TokenStream::count(Frame::Kind kind) const {
  return static_cast<std::size_t>(
      std::count_if(frames_.begin(), frames_.end(), [kind](const Frame& f) { return f.kind == kind; }));
}

std::optional<TokenStream::LiteralScanStart> TokenStream::literal_scan_start(bool loop_in_frame) {
  if (!pushed_back_.empty() || frames_.empty()) return std::nullopt;
  const Frame& f = frames_.back();
  // A macro body is always replayed from kept tokens; a #while/#for of this frame goes back to earlier tokens of
  // the file, and what the scanner reads is not kept for it to replay. (An include file is read anew, with new
  // tokens, each time it is included.)
  if (f.kind == Frame::Kind::macro) return std::nullopt;
  if (loop_in_frame) return std::nullopt;
  FileTokens& tokens = *f.tokens;
  // Tokens the lexer read ahead (lex_more reads in runs; accept() may have looked at the first) are dropped: the
  // scan reads their text itself, from the first of them.
  if (f.index < tokens.size()) {
    if (tokens[f.index].kind() == TokenKind::end_of_input) return std::nullopt;
    tokens.forget_from(f.index);
  }
  return LiteralScanStart{tokens.lexed_to, 0};
}

void TokenStream::literal_scan_commit(const LiteralScanStart& start, const LexPosition& to, std::uint64_t tokens) {
  Frame& f = frames_.back();
  f.index += start.ahead;   // the token lexed ahead was the scan's first
  f.tokens->lexed_to = to;
  tokens_read_ += tokens;
}

bool TokenStream::literal_scan_allows(std::uint64_t tokens, std::size_t items, const LexPosition& at,
                                      std::size_t scan_begin) {
  constexpr std::size_t kCheckItems = 4096;
  if (items % kCheckItems != 0) return !options_.max_tokens || tokens_read_ + tokens <= options_.max_tokens;
  if (options_.cancel && options_.cancel->load(std::memory_order_relaxed))
    fail(SourceLoc{frames_.back().file->name, at.line, at.column}, "interrupted while parsing");
  // The frame owns no const file: files_ holds it. The scan never goes back before `at`, and no loop replays it.
  if (items > 0) const_cast<SourceFile&>(*frames_.back().file).release(scan_begin, at.offset);
  // Past the token limit the ordinary reading takes over and reports it where it is reached.
  return !options_.max_tokens || tokens_read_ + tokens <= options_.max_tokens;
}

// The level count makes the limit the same everywhere; the stack check is the safety net for builds with much
// larger frames (sanitizers, -O0) and for threads with small stacks, where 500 levels may not fit.
TokenReader::NestingGuard::NestingGuard(TokenReader& in, const Token& at) : in_(in) {
  ++in_.nesting_;
  const char* lowest = stack_lowest_address();
  const char* here = static_cast<const char*>(__builtin_frame_address(0));
  const bool stack_full = lowest && here - lowest < kStackReserve;
  if (in_.nesting_ > kMaxNesting || stack_full) {
    const int levels = in_.nesting_;
    --in_.nesting_;   // the destructor does not run when the constructor throws
    in_.fail_at(at, "expressions or blocks nested too deeply (" +
                        (stack_full ? "the stack is full at " + std::to_string(levels) + " levels"
                                    : "more than " + std::to_string(kMaxNesting) + " levels") +
                        ")");
  }
}

const Value* TokenReader::lookup(const Token& t) const { return sdl::lookup(symbols_, t); }

Token TokenReader::next() {
  while (true) {
    // A directive may itself look ahead and push a token back: that token comes first, before reading on.
    // Tokens pushed back by peek_raw() are not processed yet, so they go through the same checks; tokens put
    // back after next() are, and are not processed twice (no second deprecation warning).
    // Constructed from its source, not default-constructed and assigned: zero-filling a Token first was a
    // quarter of this function's time.
    if (!stream_.has_pushed_back() && quick_directive()) continue;
    Token t = !stream_.has_pushed_back() ? raw() : pop_pushed_back();
    if (t.processed) return t;
    // A directive or macro call reads its operands with next(), which may run another directive or call before
    // the first one returns (`#declare A = #declare B = …`, `M(M(M(…)))`): they nest like expressions.
    if (t.is("#")) {
      const NestingGuard guard(*this, t);
      directives_.run(t);
      continue;
    }
    if (t.kind == TokenKind::identifier && !reserved(t)) {
      const Value* v = t.name ? symbols_.find(t.name) : symbols_.find(t.text);
      if (v && std::holds_alternative<Boxed<MacroDefinition>>(*v)) {
        const NestingGuard guard(*this, t);
        directives_.call_macro(t);
        continue;
      }
      if (v) process_identifier(t, v);
    }
    t.processed = true;
    return t;
  }
}

bool TokenReader::quick_directive() {
  if (options_.max_tokens || !nesting_room()) return false;
  const Frame& f = stream_.frame();
  const LexedToken& hash = lexed(*f.tokens, f.index);
  if (!plain_symbol(&hash, '#')) return false;
  FileTokens& tokens = *f.tokens;
  const std::size_t word_index = f.index + 1;
  const LexedToken& word = lexed(tokens, word_index);
  const DirectiveRunner::Quick kind = directives_.quick_word(word);
  if (kind == DirectiveRunner::Quick::none) return false;
  // The tokens raw() would have read (the runner takes the word of #declare from the kept token), against the
  // cancel check; where it is due, raw() makes it.
  const std::uint32_t counted = kind != DirectiveRunner::Quick::end ? 1 : 2;
  if (options_.cancel && !stream_.count_for_cancel_check(counted)) return false;
  // Between statements of the main file, outside any loop, the tokens read so far are not needed again.
  if (between_statements_ && nesting_ == 0 && stream_.depth() == 1 && directives_.none_open())
    tokens.release_before(f.index);
  stream_.step(2);   // the '#' and the word
  // next()'s NestingGuard, which nesting_room() has just let in.
  ++nesting_;
  struct Leave {
    int& nesting;
    ~Leave() { --nesting; }
  } leave{nesting_};
  directives_.quick(kind, tokens, word_index);
  return true;
}

void TokenReader::process_identifier(Token& t, const Value* v) {
  if (symbols_.any_deprecated())
    if (auto* d = symbols_.deprecation(std::string(t.text)); d && !d->shown) {
      if (d->once) d->shown = true;
      warn(t.loc, d->message);
    }
  // POV-Ray resolves `A[i]…` where it reads the name (Read_Symbol): the token then stands for the element, so
  // every place that takes an identifier of some type takes an element of that type.
  while (const auto* array = std::get_if<std::shared_ptr<ArrayValue>>(v)) {
    if (!ahead_is("[")) return;
    const std::shared_ptr<ArrayValue> keep = *array;   // the subscripts may run code that reassigns the name
    Token last = t;
    const std::size_t index = arrays_.parse_subscripts(*keep, std::string(t.text), last);
    const auto& element = keep->elements[index];
    if (last.loc.file == t.loc.file && last.end.offset > t.begin.offset)
      t.text = std::string_view(t.text.data(), last.end.offset - t.begin.offset);
    if (!element)
      fail_at(t, "the array element " + std::string(t.text) + " is read before any value was assigned to it");
    t.element = std::make_shared<const TokenValue>(TokenValue{*element});
    v = &t.element->value;
  }
}

const Token& TokenReader::peek_raw() {
  while (true) {
    // The token looked at stays pushed back (it is called after every operand: no pop and push again).
    if (!stream_.has_pushed_back()) stream_.unget(raw());
    const Token& t = stream_.pushed_back();
    // The #end of the running macro is exempt (POV-Ray checks it first): it returns, and the look goes on in
    // the caller. A `#` comes back raw, so the frame still stands just after it.
    if (t.is("#") && directives_.running_macro_here()) {
      const Frame& f = stream_.frame();
      const LexedToken& k = lexed(*f.tokens, f.index);
      const std::string_view text(f.file->text.data() + k.offset, k.length());
      if (k.kind() == TokenKind::identifier && text == "end") {
        const Token word = make_token(*f.tokens, k);
        stream_.drop_pushed_back();
        stream_.step();
        directives_.end(word);
        continue;
      }
    }
    return t;
  }
}

const Token& TokenReader::peek() {
  stream_.unget(next());
  return stream_.pushed_back();
}

TokenReader::Ahead TokenReader::raw_ahead_full() {
  // The #end of the running macro, which peek_raw() runs before looking on in the caller, read from the kept
  // tokens (a macro's value is followed by it on every call): the same checks, no Token for '#', 'end' or what
  // follows in the caller when that is plain.
  while (!stream_.has_pushed_back() && !options_.max_tokens && directives_.end_running_macro_ahead()) {
    const Frame& caller = stream_.frame();
    const LexedToken& k = lexed(*caller.tokens, caller.index);
    if (k.kind() != TokenKind::end_of_input && !plain_symbol(&k, '#')) return {k.kind(), text_of(k)};
  }
  const Token& raw_look = peek_raw();   // a frame ends or a directive may follow: the full look
  if (!raw_operator_look_ && raw_look.is("#")) {
    // Outside the contexts of RawOperatorLook the directive runs now, as POV-Ray's Get_Token runs it, and the
    // look goes on after it: next() takes the '#' peek_raw() left pushed back and runs its directive.
    const Token& t = peek();
    return {t.kind, t.text};
  }
  return {raw_look.kind, raw_look.text};
}

const LexedToken* TokenReader::plain_ahead() {
  if (stream_.has_pushed_back()) return nullptr;
  const Frame& f = stream_.frame();
  const LexedToken& k = lexed(*f.tokens, f.index);
  switch (k.kind()) {
    case TokenKind::number:
    case TokenKind::string: return &k;
    case TokenKind::symbol: return plain_symbol(&k, '#') ? nullptr : &k;
    case TokenKind::identifier: {
      if (symbols_.is_reserved(k.payload)) return &k;
      if (symbols_.any_deprecated()) return nullptr;
      const Value* v = symbols_.find(k.payload);
      if (v && (std::holds_alternative<Boxed<MacroDefinition>>(*v) ||
                std::holds_alternative<std::shared_ptr<ArrayValue>>(*v)))
        return nullptr;
      return &k;
    }
    case TokenKind::end_of_input: break;
  }
  return nullptr;
}

void TokenReader::consume_plain() {
  if (options_.max_tokens) {   // next() counts it and reports the limit as everywhere else
    next();
    return;
  }
  stream_.step();
}

void TokenReader::skip_ahead() {
  if (!stream_.has_pushed_back()) consume_plain();
  else stream_.drop_pushed_back();   // a symbol, which next() would return as it is
}

void TokenReader::skip_expected(char symbol, std::string_view context) {
  if (plain_symbol(plain_ahead(), symbol)) consume_plain();
  else expect(std::string_view(&symbol, 1), context);
}

bool TokenReader::nesting_room() const {
  const char* lowest = stack_lowest_address();
  const char* here = static_cast<const char*>(__builtin_frame_address(0));
  return nesting_ < kMaxNesting && !(lowest && here - lowest < kStackReserve);
}

// The ExpressionParser's (expression_parser.hpp), defined here beside plain_ahead() and nesting_room(), which it
// inlines: once per operand. Defined in expressions.cpp, with the two as calls, it cost 1.1% more instructions on
// the parse_declares benchmark.
bool ExpressionParser::fast_operand(Numeric& out) {
  // The token limit is counted by next() alone; a component selector (.x) goes through parse_postfix.
  if (in().token_limit_ || !nesting_room()) return false;
  const LexedToken* k = plain_ahead();
  if (!k) return false;
  const Frame& f = token_stream().frame();
  if (k->kind() == TokenKind::number) {
    out = Numeric::scalar(f.tokens->number(*k));
  } else if (k->kind() == TokenKind::identifier && !symbol_table().is_reserved(k->payload)) {
    const Value* v = symbol_table().find(k->payload);
    const Numeric* n = v ? std::get_if<Numeric>(v) : nullptr;
    if (!n) return false;   // undeclared, or no number: parse_primary says what it is
    out = *n;
  } else {
    return false;
  }
  token_stream().step();
  if (raw_ahead().is(".")) out = parse_postfix(out);
  return true;
}

Token TokenReader::expect(std::string_view symbol, std::string_view context) {
  Token t = next();
  if (!t.is(symbol)) fail_expected(t, "'" + std::string(symbol) + "'" + std::string(context));
  return t;
}

bool TokenReader::accept(std::string_view symbol) {
  // A plain token ahead is looked at where it stands: no Token made, none pushed back.
  if (const LexedToken* k = plain_ahead()) {
    if ((k->kind() != TokenKind::symbol && k->kind() != TokenKind::identifier) || text_of(*k) != symbol)
      return false;
    consume_plain();
    return true;
  }
  Token t = next();
  if (t.is(symbol)) return true;
  unget(t);
  return false;
}

std::string TokenReader::expect_identifier_raw(std::string_view context) {
  Token t = raw();
  if (t.kind != TokenKind::identifier) fail_expected(t, std::string("an identifier ") + std::string(context));
  if (reserved(t))
    fail_at(t, "'" + std::string(t.text) + "' is a reserved word and cannot be used as an identifier " +
                   std::string(context));
  return std::string(t.text);
}

const SourceFile& TokenStream::file_of(const SourceLoc& loc) const {
  for (const auto& f : files_)
    if (f->name == loc.file || (loc.file && *f->name == *loc.file)) return *f;
  return *files_.front();
}

ParseError TokenStream::error(const SourceLoc& loc, const std::string& message) const {
  return ParseError(loc, message, std::string(file_of(loc).line_text(loc.line)), reached_from());
}

void TokenStream::fail(const SourceLoc& loc, const std::string& message) const { throw error(loc, message); }


std::string TokenStream::reached_from() const {
  // Runaway recursion can stack hundreds of frames: the innermost and outermost levels say enough.
  constexpr std::size_t kInner = 10, kOuter = 5;
  const std::size_t levels = frames_.empty() ? 0 : frames_.size() - 1;
  std::string out;
  for (std::size_t k = 0; k < levels; ++k) {
    if (levels > kInner + kOuter + 1 && k == kInner) {
      out += "\n  ... " + std::to_string(levels - kInner - kOuter) + " more levels ...";
      k = levels - kOuter - 1;
      continue;
    }
    const Frame& f = frames_[frames_.size() - 1 - k];
    if (!out.empty()) out += '\n';
    if (f.kind == Frame::Kind::macro)
      out += "  in macro " + std::string(f.macro_name) + " called from " + f.origin.to_string();
    else
      out += "  included from " + f.origin.to_string();
  }
  return out;
}

void TokenStream::seek(Position p) {
  frames_.resize(p.frame + 1);
  frames_.back().index = p.index;
  pushed_back_.clear();
}

TokenStream::ReplayPoint TokenStream::replay_point() {
  const Frame& f = frames_.back();
  f.tokens->keep_from(f.index);
  return {f.file, f.tokens, f.index};
}

void TokenStream::push_file(const std::filesystem::path& path, const Token& at, Frame::Kind kind) {
  const auto includes = std::count_if(frames_.begin(), frames_.end(),
                                      [](const Frame& f) { return f.kind == Frame::Kind::include; });
  if (static_cast<std::size_t>(includes) >= kMaxIncludeDepth)
    fail(at.loc, "too many nested #include files (at most " + std::to_string(kMaxIncludeDepth) +
                    "; does a file include itself?)");
  auto file = std::make_unique<SourceFile>();
  file->path = path;
  file->name = file_name(path.string());
  try {
    file->text = read_text_file(path);
  } catch (const std::exception& e) {
    fail(at.loc, e.what());
  }
  frames_.push_back(frame_for(*file, 0, kind, at.loc, {}));
  files_.push_back(std::move(file));
}

}  // namespace povtrace::sdl

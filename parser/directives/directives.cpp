// Language directives (povray-sdl-and-geometry.md §4). Conditionals and loops keep a control stack; loops and
// macros replay source by seeking the frame back to a remembered position (§1 item 4).
#include <cmath>
#include <functional>
#include <iostream>

#include "parser/directives/directive_services.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kConditionEpsilon = 1e-10;   // #if is true iff |F| > 1e-10 (§4)

// POV-Ray warns about a deprecated identifier wherever it reads the name — also as the target of #declare,
// #local and #undef — but not in #ifdef or defined().
void warn_if_deprecated(SymbolTable& symbols, const Token& name,
                        const std::function<void(const SourceLoc&, const std::string&)>& warn) {
  if (!symbols.any_deprecated() || name.kind != TokenKind::identifier) return;
  if (auto* d = symbols.deprecation(std::string(name.text)); d && !d->shown) {
    if (d->once) d->shown = true;
    warn(name.loc, d->message);
  }
}

bool opens_block(std::string_view word) {
  return word == "if" || word == "ifdef" || word == "ifndef" || word == "while" || word == "for" ||
         word == "switch" || word == "macro";
}
}  // namespace

void DirectiveRunner::run(const Token& hash) {
  // #declare and #local, the directives loops run most, are recognised from the kept token: no Token is made for
  // the word (directive_declare reads on from after it). With a token limit, raw() counts the word.
  if (const LexedToken* k = plain_ahead(); k && !options_.max_tokens && k->kind() == TokenKind::identifier) {
    if (k->payload == word_declare_ || k->payload == word_local_) {
      const bool local = k->payload == word_local_;
      stream_.step();
      return directive_declare(local);
    }
  }
  Token word = raw();
  // POV-Ray ignores a '#' that no directive name follows: the next token is read as if the '#' were not
  // there (a sample scene writes `look_at <0,2,0>#` before its closing brace).
  if (word.kind != TokenKind::identifier) {
    warn(hash.loc, "'#' without a directive name is ignored");
    unget(word);
    return;
  }
  const std::string_view w = word.text;
  if (w == "version") return directive_version(word);
  if (w == "declare") return directive_declare(false);
  if (w == "local") return directive_declare(true);
  if (w == "undef") return directive_undef();
  if (w == "include") return directive_include(hash);   // the chain of an error names the #include
  if (w == "if") return directive_if(word, 0);
  if (w == "ifdef") return directive_if(word, 1);
  if (w == "ifndef") return directive_if(word, 2);
  if (w == "else") return directive_else(word, false);
  if (w == "elseif") return directive_else(word, true);
  if (w == "end") return directive_end(word);
  if (w == "while") return directive_while(word);
  if (w == "for") return directive_for(word);
  if (w == "macro") return directive_macro(word);
  if (w == "debug" || w == "warning" || w == "error" || w == "render" || w == "statistics")
    return directive_message(word, std::string(w));
  if (w == "default") return parse_default(word);
  if (w == "switch") return directive_switch(word);
  if (w == "case") return directive_case(word, false);
  if (w == "range") return directive_case(word, true);
  if (w == "break") return directive_break(word);
  if (w == "fopen") return directive_fopen(word);
  if (w == "fclose") return directive_fclose(word);
  if (w == "read") return directive_read(word);
  if (w == "write") return directive_write(word);
  warn(hash.loc, "'#" + std::string(w) + "' is not a directive: the '#' is ignored, as POV-Ray does");
  unget(word);
}

void DirectiveRunner::directive_declare(bool local) {
  // The name. A plain identifier is taken from its kept token (loops run #declare every round), its Token made
  // only where a message or an element assignment needs it; anything else is read by raw() as before.
  std::optional<Token> name_token;
  FileTokens* kept_tokens = nullptr;
  std::size_t kept_index = 0;
  SymbolTable::NameId id = 0;
  std::string_view name_text;
  if (const Frame& f = stream_.frame(); !stream_.has_pushed_back() && !options_.max_tokens && !symbols_.any_deprecated()) {
    const LexedToken& k = lexed(*f.tokens, f.index);
    if (k.kind() == TokenKind::identifier && !symbols_.is_reserved(k.payload)) {
      kept_tokens = f.tokens;
      kept_index = f.index;
      stream_.step();
      id = k.payload;
      name_text = text_of(k);
    }
  }
  auto token = [&]() -> const Token& {
    if (!name_token) name_token = make_token(*kept_tokens, (*kept_tokens)[kept_index]);
    return *name_token;
  };
  // #declare deprecated [once] "message" Name = … (§4): later reads of Name warn.
  std::optional<SymbolTable::Deprecation> deprecation;
  if (!kept_tokens) {
    name_token = raw();
    if (name_token->is("deprecated")) {
      deprecation.emplace();
      if (peek_raw().is("once")) {
        next();
        deprecation->once = true;
      }
      if (starts_string(peek_raw())) deprecation->message = parse_string();   // optional
      // The name is read raw (it is being declared): take it back from the look-ahead.
      name_token = stream_.raw_or_pushed_back();
    }
    if (name_token->kind != TokenKind::identifier) fail_expected(*name_token, "an identifier after #declare");
    if (reserved(*name_token))   // by its NameId where the token has one
      fail_at(*name_token, "'" + std::string(name_token->text) + "' is a reserved word and cannot be declared");
    name_text = name_token->text;
  }
  const std::string_view name = name_text;   // in the file's text: no copy per #declare
  if (deprecation && deprecation->message.empty())
    deprecation->message = "Identifier '" + std::string(name) + "' was declared deprecated.";
  if (!kept_tokens) {
    warn_if_deprecated(symbols_, *name_token, [this](const SourceLoc& l, const std::string& m) { warn(l, m); });
    id = name_token->name ? name_token->name : symbols_.intern(name);
  }
  if (ahead_is("[")) {
    const Value* v = symbols_.find(id);
    if (v && std::holds_alternative<std::shared_ptr<ArrayValue>>(*v))
      return directive_declare_element(token(), local);
  }
  if (plain_symbol(plain_ahead(), '=')) {
    consume_plain();
  } else if (Token eq = next(); !eq.is("=")) {
    fail_expected(eq, "'=' after #declare " + std::string(name));
  }
  // The table the value goes to is fixed now, before the value is parsed (POV-Ray's Parse_Declare): #local's is
  // the current one; #declare's the one holding the visible entry, or the global table.
  const std::size_t target_level = local ? symbols_.depth() - 1 : symbols_.level_of(id).value_or(0);
  const RawOperatorLook raw_look(*this);   // the value of a #declare: POV-Ray's Ok_To_Declare is off
  call_macros_ahead();
  if (numeric_ahead()) {
    // A number or vector, what try_parse_rvalue() makes of it without a Token, and the steps below for it: stored
    // straight into an entry that holds a number already (loops assign the same names every round).
    const Numeric n = parse_additive().stored();
    if (const Value* visible = symbols_.find(id);
        !kept_tokens || (visible && std::holds_alternative<std::shared_ptr<const FunctionValue>>(*visible)))
      check_function_redeclaration(token(), local, Value(n));
    symbols_.assign_numeric_at(id, target_level, n);
    if (deprecation) symbols_.deprecate(std::string(name), std::move(*deprecation));
    if (raw_ahead().is(";")) skip_ahead();
    else if (language_version() >= 350)
      fail_expected(peek_raw(), "';' after the value of " + std::string(name));
    return;
  }
  std::optional<Value> value;
  {
    Token first = next();
    // Only a numeric value keeps the raw look: in a block (`#declare S = sphere { 0, M() * 0.5 }`) POV-Ray runs a
    // directive met after an operand, as it does outside a #declare.
    const Value* held = first.kind == TokenKind::identifier ? lookup(first) : nullptr;
    const bool numeric = first.kind == TokenKind::number || first.kind == TokenKind::symbol ||
                         (held && std::holds_alternative<Numeric>(*held));
    const RawOperatorLook look(*this, numeric);
    value = try_parse_rvalue(first);
    if (!value) fail_expected(first, "a value (number, vector, colour, string, object, texture, pigment, finish, "
                                     "interior or camera) for " + std::string(name));
  }
  // Float, vector and colour values need the ';' in #version ≥ 3.5 (§4).
  const bool needs_semicolon = std::holds_alternative<Numeric>(*value) && language_version() >= 350;
  // (Its checks concern functions only: the kept name's Token is made where one is involved.)
  if (const Value* visible = symbols_.find(id);
      !kept_tokens || std::holds_alternative<std::shared_ptr<const FunctionValue>>(*value) ||
      (visible && std::holds_alternative<std::shared_ptr<const FunctionValue>>(*visible)))
    check_function_redeclaration(token(), local, *value);
  // Store before looking for the optional ';': that look must not run the next directive (a `#declare` using
  // this name, or the `#end` of the macro whose local this is) while this one is unfinished.
  symbols_.assign_at(id, target_level, std::move(*value));
  if (deprecation) symbols_.deprecate(std::string(name), std::move(*deprecation));
  if (raw_ahead().is(";")) skip_ahead();
  else if (needs_semicolon) fail_expected(peek_raw(), "';' after the value of " + std::string(name));
}

void DirectiveRunner::directive_undef() {
  Token name = raw();
  if (name.kind != TokenKind::identifier) fail_expected(name, "an identifier after #undef");
  warn_if_deprecated(symbols_, name, [this](const SourceLoc& l, const std::string& m) { warn(l, m); });
  // #undef A[i] makes the element unassigned again.
  if (frame_ahead_is("["))
    if (auto ref = parse_element_reference(name)) {
      ref->array->elements[ref->index].reset();
      return;
    }
  if (!symbols_.undefine(std::string(name.text)))
    warn(name.loc, "#undef of '" + std::string(name.text) + "', which is not declared");
}

std::optional<std::filesystem::path> DirectiveRunner::find_include(const std::string& name) const {
  // Candidate names (§4 #include): "x.inc" as given first; otherwise x.inc, x.INC, then the bare name.
  std::vector<std::string> candidates;
  const bool has_inc = name.size() > 4 && (name.ends_with(".inc") || name.ends_with(".INC"));
  if (has_inc) candidates = {name, name + ".inc", name + ".INC"};
  else candidates = {name + ".inc", name + ".INC", name};
  // Every file-system query takes an error_code: a name the system rejects (too long, say) is simply not found,
  // and the caller reports "cannot find include file" with its position instead of an exception escaping.
  std::error_code ec;
  std::vector<std::filesystem::path> dirs;
  if (auto cwd = std::filesystem::current_path(ec); !ec) dirs.push_back(std::move(cwd));
  for (const auto& d : options_.library_paths) dirs.push_back(d);
  for (const auto& candidate : candidates) {
    const std::filesystem::path p(candidate);
    if (p.is_absolute()) {
      if (std::filesystem::is_regular_file(p, ec)) return p;
      continue;
    }
    for (const auto& d : dirs)
      if (std::filesystem::is_regular_file(d / p, ec)) return d / p;
  }
  return std::nullopt;
}

void DirectiveRunner::directive_include(const Token& at) {
  Token name_token = next();
  if (name_token.kind != TokenKind::string) fail_expected(name_token, "a file name string after #include");
  const std::string name = string_value(name_token, *stream_.frame().file, false);
  auto path = find_include(name);
  if (!path) {
    std::string searched = "the working directory";
    for (const auto& d : options_.library_paths) searched += ", " + d.string();
    fail_at(name_token, "cannot find include file \"" + name + "\" (searched " + searched + ")");
  }
  push_file(*path, at, Frame::Kind::include);
}

bool DirectiveRunner::condition_in_parens() {
  const RawOperatorLook raw_look(*this);   // POV-Ray's Parse_Cond_Param
  skip_expected('(', " (conditions are written in parentheses)");
  const double v = parse_float_full();
  skip_expected(')', " closing the condition");
  return std::fabs(v) > kConditionEpsilon;
}

bool DirectiveRunner::identifier_defined_in_parens() {
  expect("(", " (write #ifdef (Name))");
  return parse_defined_identifier();
}

// Skips a false branch: tokens are still lexed (comments and strings must be well formed) but nothing is
// evaluated; nested blocks are counted so that only this level's #else/#elseif/#end stop the skip.
std::string DirectiveRunner::skip_branch(const Token& opener, bool stop_at_else) {
  int depth = 0;
  while (true) {
    Token t = raw();
    if (t.kind == TokenKind::end_of_input)
      fail(opener.loc, "this #" + std::string(opener.text) + " has no matching #end");
    if (!t.is("#")) continue;
    Token w = raw();
    if (w.kind != TokenKind::identifier) continue;
    if (opens_block(w.text)) { ++depth; continue; }
    if (w.text == "end") {
      if (depth == 0) return "end";
      --depth;
      continue;
    }
    if (depth == 0 && stop_at_else && (w.text == "else" || w.text == "elseif")) return std::string(w.text);
  }
}

void DirectiveRunner::directive_if(const Token& at, int kind) {
  bool taken = kind == 0 ? condition_in_parens() : identifier_defined_in_parens();
  if (kind == 2) taken = !taken;
  while (!taken) {
    const std::string found = skip_branch(at, true);
    if (found == "end") return;
    if (found == "else") break;
    taken = condition_in_parens();   // #elseif
  }
  Control c;
  c.kind = Control::Kind::if_branch;
  c.frame = stream_.depth() - 1;
  c.loc = at.loc;
  controls_.push_back(c);
}

// Reaching #else/#elseif while executing means the branch before it ran: skip to the #end.
void DirectiveRunner::directive_else(const Token& at, bool is_elseif) {
  // In a #switch, reaching #else while executing a matched section falls through into it, as C's default does
  // (POV-Ray 3.7 behaves so, although its documentation says otherwise).
  if (!is_elseif && !controls_.empty() && controls_.back().kind == Control::Kind::switch_block) return;
  if (controls_.empty() || controls_.back().kind != Control::Kind::if_branch)
    fail_at(at, std::string("#") + (is_elseif ? "elseif" : "else") + " without a matching #if");
  if (is_elseif) {
    // The condition is not evaluated (a branch was already taken), but it must be skipped as tokens.
    expect("(", " after #elseif");
    int depth = 1;
    while (depth > 0) {
      Token t = raw();
      if (t.kind == TokenKind::end_of_input) fail_expected(t, "')' closing the #elseif condition");
      if (t.is("(")) ++depth;
      if (t.is(")")) --depth;
    }
  }
  while (skip_branch(at, true) != "end") {
  }
  controls_.pop_back();
}

void DirectiveRunner::directive_end(const Token& at) {
  if (controls_.empty()) fail_at(at, "#end without a matching #if, #while, #for or #macro");
  Control& c = controls_.back();
  switch (c.kind) {
    case Control::Kind::if_branch:
      controls_.pop_back();
      return;
    case Control::Kind::switch_block:
      controls_.pop_back();
      return;
    case Control::Kind::macro_call:
      if (stream_.depth() - 1 != c.frame) fail_at(at, "#end of a macro in another file than its #macro");
      return_from_macro();
      return;
    case Control::Kind::while_loop: {
      if (stream_.depth() - 1 != c.frame) fail_at(at, "a #while loop must end in the file it started in");
      const Control loop = c;
      stream_.seek(loop.resume);
      if (condition_in_parens()) return;
      controls_.pop_back();
      Token opener = at;
      opener.text = "while";
      skip_branch(opener, false);
      return;
    }
    case Control::Kind::for_loop: {
      if (stream_.depth() - 1 != c.frame) fail_at(at, "a #for loop must end in the file it started in");
      const Value* v = symbols_.find(c.for_variable);
      if (!v || !std::holds_alternative<Numeric>(*v))
        fail_at(at, "the #for variable '" + c.for_variable + "' is no longer a float");
      const double value = std::get<Numeric>(*v).v[0] + c.for_step;
      symbols_.local(c.for_variable, Numeric::scalar(value));
      const bool go_on = c.for_step > 0 ? value <= c.for_end + 1e-10 : value >= c.for_end - 1e-10;
      if (go_on) { stream_.seek(c.resume); return; }
      controls_.pop_back();
      return;
    }
  }
}

// #switch (F) must be followed by #case or #range (§4). A matched section runs and falls through the later
// #case/#range/#else lines (they are still parsed) until #break or #end; an unmatched one is skipped.
void DirectiveRunner::directive_switch(const Token& at) {
  Control c;
  c.kind = Control::Kind::switch_block;
  c.frame = stream_.depth() - 1;
  c.loc = at.loc;
  c.switch_value = [&] {
    const RawOperatorLook raw_look(*this);
    expect("(", " (conditions are written in parentheses)");
    const double v = parse_float_full();
    expect(")", " closing the condition");
    return v;
  }();
  Token hash = raw();
  Token word = hash.is("#") ? raw() : hash;
  if (!hash.is("#") || !(word.is("case") || word.is("range")))
    fail_expected(word, "#case or #range after #switch");
  controls_.push_back(c);
  if (!case_matches(word)) skip_switch_section(at);
}

bool DirectiveRunner::case_matches(const Token& word) {
  const RawOperatorLook raw_look(*this);
  const double v = controls_.back().switch_value;
  expect("(", " (conditions are written in parentheses)");
  const double a = parse_float_full();
  if (word.is("case")) {
    expect(")", " closing the condition");
    return std::fabs(v - a) < kConditionEpsilon;
  }
  expect(",", " between the bounds of #range (Low, High)");
  const double b = parse_float_full();
  expect(")", " closing the condition");
  return v >= a && v <= b;
}

void DirectiveRunner::skip_switch_section(const Token& at) {
  int depth = 0;
  while (true) {
    Token t = raw();
    if (t.kind == TokenKind::end_of_input) fail(at.loc, "this #switch has no matching #end");
    if (!t.is("#")) continue;
    Token w = raw();
    if (w.kind != TokenKind::identifier) continue;
    if (opens_block(w.text)) { ++depth; continue; }
    if (w.text == "end") {
      if (depth == 0) { controls_.pop_back(); return; }
      --depth;
      continue;
    }
    if (depth > 0) continue;
    if (w.text == "else") return;
    if ((w.text == "case" || w.text == "range") && case_matches(w)) return;
  }
}

// Reached while executing a matched section: the condition is parsed but not tested again (fall-through).
void DirectiveRunner::directive_case(const Token& at, bool is_range) {
  if (controls_.empty() || controls_.back().kind != Control::Kind::switch_block)
    fail_at(at, std::string("#") + (is_range ? "range" : "case") + " without a matching #switch");
  case_matches(at);
}

// #break (§4): leaves the innermost #switch, #while or #for — skipping to its #end, through any #if around the
// #break — or returns from the current macro.
void DirectiveRunner::directive_break(const Token& at) {
  while (true) {
    if (controls_.empty()) fail_at(at, "#break outside a #switch, #while, #for or macro");
    const Control c = controls_.back();
    if (c.kind == Control::Kind::macro_call) {
      if (stream_.depth() - 1 != c.frame) fail_at(at, "#break in another file than the macro it returns from");
      return_from_macro();
      return;
    }
    Token opener = at;
    opener.loc = c.loc;
    opener.text = c.kind == Control::Kind::if_branch ? "if" : c.kind == Control::Kind::switch_block ? "switch"
                  : c.kind == Control::Kind::while_loop ? "while" : "for";
    skip_branch(opener, false);
    controls_.pop_back();
    if (c.kind != Control::Kind::if_branch) return;
  }
}

void DirectiveRunner::directive_while(const Token& at) {
  Control c;
  c.kind = Control::Kind::while_loop;
  c.frame = stream_.depth() - 1;
  c.resume = stream_.position();   // the condition is re-parsed at every #end
  c.loc = at.loc;
  if (stream_.has_pushed_back()) fail_at(at, "internal: #while after a look-ahead");
  if (!condition_in_parens()) { skip_branch(at, false); return; }
  controls_.push_back(c);
}

void DirectiveRunner::directive_for(const Token& at) {
  expect("(", " after #for");
  const std::string var = expect_identifier_raw("for the #for loop variable");
  expect(",", " after the #for variable");
  const double start = parse_float();
  expect(",", " after the #for start value");
  const double end = parse_float();
  double step = 1;
  if (accept(",")) step = parse_float();
  Token close = expect(")", " closing #for");
  if (step == 0) fail_at(close, "the #for step must not be zero");
  symbols_.local(var, Numeric::scalar(start));
  const bool run = step > 0 ? start <= end + 1e-10 : start >= end - 1e-10;
  if (!run) { skip_branch(at, false); return; }
  Control c;
  c.kind = Control::Kind::for_loop;
  c.frame = stream_.depth() - 1;
  c.resume = stream_.position();
  c.for_variable = var;
  c.for_end = end;
  c.for_step = step;
  c.loc = at.loc;
  controls_.push_back(c);
}

void DirectiveRunner::directive_macro(const Token& at) {
  MacroDefinition m;
  const std::string name = expect_identifier_raw("for the macro name");
  Token open = raw();
  if (!open.is("(")) fail_expected(open, "'(' after the macro name");
  Token t = raw();
  while (!t.is(")")) {
    if (t.kind != TokenKind::identifier || is_reserved_word(t.text))
      fail_expected(t, "a parameter name or ')' in the definition of macro " + name);
    m.parameters.emplace_back(t.text);
    m.parameter_ids.push_back(symbols_.intern(t.text));
    t = raw();
    if (t.is(",")) t = raw();
  }
  const TokenStream::ReplayPoint body = stream_.replay_point();   // every call replays the body
  m.file = body.file;
  m.tokens = body.tokens;
  m.body = body.index;
  m.loc = at.loc;
  Token opener = at;
  skip_branch(opener, false);
  symbols_.declare(name, std::move(m));   // macros always live in the global table (§3)
}

void DirectiveRunner::directive_message(const Token& at, const std::string& kind) {
  const std::string text = parse_string();
  if (kind == "error") fail_at(at, "#error: " + text);
  std::string out = kind == "warning" ? format_diagnostic(at.loc, "warning", text, {}) : text;
  if (kind == "warning" && options_.warning_level < 5) return;
  if (options_.classified_sink)
    options_.classified_sink(kind == "warning" ? ParseOptions::MessageKind::warning : ParseOptions::MessageKind::debug,
                             out);
  else if (options_.message_sink) options_.message_sink(out);
  else std::cerr << out << (kind == "warning" ? "\n" : "");
}

void DirectiveRunner::leaving_include(std::size_t frame, const SourceFile& file) {
  if (!controls_.empty() && controls_.back().frame == frame)
    fail(controls_.back().loc,
         "this directive is not closed in its file: expected '#end' before the end of '" + *file.name + "'");
  symbols_.pop_scope();
}

void DirectiveRunner::check_closed_at_end() const {
  if (!controls_.empty()) {
    const Control& open = controls_.back();
    fail(open.loc, "this directive is not closed: expected '#end' before the end of the file");
  }
}

}  // namespace povtrace::sdl

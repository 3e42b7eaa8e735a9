// User file I/O (povray-sdl-and-geometry.md §4): #fopen Id "name" read|write|append, #read (Id, Var, …),
// #write (Id, item, …), #fclose Id. A file being read is lexed with the SDL lexer, as POV-Ray does: items are
// signed floats, 2–5 component vectors and string literals separated by commas; at its end the file identifier
// is undefined, so `#while (defined(Id))` loops stop. Writes go straight to the file.
//
// Confinement: povtrace reads and writes user files only inside the scene file's directory tree or the working
// directory's (symbolic links resolved); any other path is an error naming it.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "parser/directives/directive_services.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

struct UserFile {
  std::string name;          // as written in #fopen
  bool reading = false;
  SourceFile data;           // read: the whole file, lexed item by item
  LexPosition pos;
  std::ofstream out;         // write, append
};

namespace {
namespace fs = std::filesystem;

bool is_under(const fs::path& p, const fs::path& root) {
  auto r = root.begin(), i = p.begin();
  for (; r != root.end(); ++r, ++i) {
    if (r->empty()) continue;   // a trailing separator
    if (i == p.end() || *i != *r) return false;
  }
  return true;
}

fs::path canonical_directory(const fs::path& dir) {
  std::error_code ec;
  fs::path p = fs::weakly_canonical(dir, ec);
  if (ec) p = dir;
  if (p.filename().empty() && p.has_parent_path() && p != p.root_path()) p = p.parent_path();
  return p;
}

std::string format_g(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

[[noreturn]] void fail_in_data(const UserFile& f, const Token& t, const std::string& message) {
  throw ParseError(t.loc, message, std::string(f.data.line_text(t.loc.line)));
}

Token lex_data(UserFile& f) {
  Token t = lex_token(f.data, f.pos);
  if (t.kind != TokenKind::end_of_input) f.pos = t.end;
  return t;
}

double signed_number(UserFile& f, Token t) {
  double sign = 1;
  if (t.is("+") || t.is("-")) {
    if (t.is("-")) sign = -1;
    t = lex_data(f);
  }
  if (t.kind != TokenKind::number)
    fail_in_data(f, t, "expected a number in the data file \"" + f.name + "\"");
  return sign * t.number;
}

// One data item, then the token after it (POV-Ray's Parse_Comma). `at_end` is set when the file ends — also right
// after a last item that has no comma behind it, which is why a loop reading one item at a time runs once per
// item.
std::optional<Value> read_item(UserFile& f, bool& at_end) {
  Token t = lex_data(f);
  std::optional<Value> item;
  if (t.kind == TokenKind::end_of_input) {
    at_end = true;
    return item;
  }
  if (t.kind == TokenKind::string) {
    item = Value(string_value(t, f.data, true));
  } else if (t.is("<")) {
    Numeric n;
    n.terms = 0;
    Token c = lex_data(f);
    while (!c.is(">")) {
      if (n.terms == 5) fail_in_data(f, c, "a vector in a data file has at most 5 components");
      n.v[n.terms++] = signed_number(f, c);
      c = lex_data(f);
      if (c.is(",")) c = lex_data(f);
    }
    if (n.terms < 2) fail_in_data(f, c, "a vector in a data file needs 2 to 5 components");
    n.colour = n.terms == 5;
    item = Value(n);
  } else if (t.kind == TokenKind::number || t.is("+") || t.is("-")) {
    item = Value(Numeric::scalar(signed_number(f, t)));
  } else {
    fail_in_data(f, t, "expected a float, a vector or a string literal in the data file \"" + f.name + "\"");
  }
  // POV-Ray reads the token after an item looking for a comma and drops it whatever it is: items must be
  // separated by commas, anything else there is lost.
  if (lex_data(f).kind == TokenKind::end_of_input) at_end = true;
  return item;
}
}  // namespace

fs::path DirectiveRunner::confined_path(const std::string& name, const Token& at) const {
  std::error_code ec;
  const fs::path cwd = fs::current_path(ec);
  const fs::path written(name);
  const fs::path absolute = written.is_absolute() ? written : cwd / written;
  fs::path resolved = fs::weakly_canonical(absolute, ec);
  if (ec) fail_at(at, "cannot resolve the file name \"" + name + "\": " + ec.message());
  // A dangling symbolic link is left unresolved by weakly_canonical: it could point anywhere.
  if (fs::is_symlink(fs::symlink_status(resolved, ec)))
    fail_at(at, "the file \"" + name + "\" is a symbolic link to a missing file (" + resolved.string() + ")");
  fs::path scene_dir = stream_.main_file().path.parent_path();
  if (scene_dir.empty()) scene_dir = cwd;
  else if (scene_dir.is_relative()) scene_dir = cwd / scene_dir;
  const fs::path roots[] = {canonical_directory(scene_dir), canonical_directory(cwd)};
  for (const auto& root : roots)
    if (is_under(resolved, root)) return resolved;
  fail_at(at, "the file \"" + name + "\" (" + resolved.string() + ") is outside the scene's directory (" +
                  roots[0].string() + ") and the working directory (" + roots[1].string() +
                  "): povtrace reads and writes user files only there");
}

void DirectiveRunner::directive_fopen(const Token& at) {
  const std::string id = expect_identifier_raw("for the file after #fopen");
  Token name_token = next();
  std::string name;
  if (name_token.kind == TokenKind::string) {
    name = string_value(name_token, file_of(name_token.loc), false);   // file names are taken verbatim (§2)
  } else {
    unget(name_token);
    name = parse_string();
  }
  Token mode = next();
  if (!mode.is("read") && !mode.is("write") && !mode.is("append"))
    fail_expected(mode, "read, write or append after the file name");
  const fs::path path = confined_path(name, name_token);
  auto file = std::make_shared<UserFile>();
  file->name = name;
  if (mode.is("read")) {
    file->reading = true;
    file->data.name = file_name(path.string());
    file->data.path = path;
    try {
      file->data.text = read_text_file(path);
    } catch (const std::exception& e) {
      fail_at(name_token, "cannot open the user file \"" + name + "\" for reading: " + e.what());
    }
  } else {
    file->out.open(path, std::ios::binary | (mode.is("append") ? std::ios::app : std::ios::trunc));
    if (!file->out)
      fail_at(name_token, "cannot open the user file \"" + name + "\" for " +
                              (mode.is("append") ? "appending" : "writing") + " (" + path.string() + ")");
  }
  symbols_.declare(id, Value(std::move(file)));
  (void)at;
}

// #fclose Id: closes and undefines the file; an identifier that is no open file (one read to its end, say) is
// ignored, as POV-Ray does.
void DirectiveRunner::directive_fclose(const Token& at) {
  Token id = raw();
  if (id.kind != TokenKind::identifier) fail_expected(id, "a file identifier after #fclose");
  if (const Value* v = lookup(id); v && std::holds_alternative<std::shared_ptr<UserFile>>(*v)) {
    auto& file = *std::get<std::shared_ptr<UserFile>>(*v);
    if (file.out.is_open()) file.out.close();
    symbols_.undefine(std::string(id.text));
  }
  (void)at;
}

void DirectiveRunner::directive_read(const Token& at) {
  expect("(", " after #read");
  Token id = next();
  const Value* v = lookup(id);
  if (!v || !std::holds_alternative<std::shared_ptr<UserFile>>(*v))
    fail_expected(id, "a file identifier opened by #fopen … read");
  const std::shared_ptr<UserFile> file = std::get<std::shared_ptr<UserFile>>(*v);
  const std::string file_id(id.text);
  if (!file->reading) fail_at(id, "cannot read from \"" + file->name + "\": it is open for writing");
  // The targets are lvalues, read raw: an undeclared name is fine, and `A[i]` is not read but assigned.
  auto raw_token = [this]() { return stream_.raw_or_pushed_back(); };
  if (peek_raw().is(",")) raw_token();
  bool at_end = false;
  while (true) {
    Token t = raw_token();
    if (t.is(")")) break;
    if (t.kind != TokenKind::identifier || is_reserved_word(t.text))
      fail_expected(t, "an identifier to read into, or ')'");
    const std::string name(t.text);
    const bool subscripted = ahead_is("[");
    std::optional<ArrayValues::ElementRef> element;
    if (subscripted) element = parse_element_reference(t);
    if (!at_end) {
      std::optional<Value> item = read_item(*file, at_end);
      if (item && element) store_element(*element->array, element->index, std::move(*item), t, name);
      else if (item) symbols_.declare(name, std::move(*item));   // unknown names become globals
    }
    Token sep = next();
    if (sep.is(")")) break;
    if (!sep.is(",")) fail_expected(sep, "',' or ')' in #read");
  }
  if (at_end) symbols_.undefine(file_id);
  (void)at;
}

void DirectiveRunner::directive_write(const Token& at) {
  expect("(", " after #write");
  Token id = next();
  const Value* v = lookup(id);
  if (!v || !std::holds_alternative<std::shared_ptr<UserFile>>(*v))
    fail_expected(id, "a file identifier opened by #fopen … write");
  const std::shared_ptr<UserFile> file = std::get<std::shared_ptr<UserFile>>(*v);
  if (file->reading) fail_at(id, "cannot write to \"" + file->name + "\": it is open for reading");
  std::ofstream& out = file->out;
  while (true) {
    Token t = next();
    if (t.is(")")) break;
    if (t.is(",")) continue;
    if (t.kind == TokenKind::end_of_input) fail_expected(t, "')' closing #write");
    static const std::string_view raw_types[] = {"sint8", "uint8", "sint16be", "sint16le", "uint16be",
                                                 "uint16le", "sint32be", "sint32le"};
    if (std::find(std::begin(raw_types), std::end(raw_types), t.text) != std::end(raw_types) &&
        t.kind == TokenKind::identifier) {
      // Raw integers: each term clamped to the type's range, rounded, written in the stated byte order.
      const std::string_view k = t.text;
      const bool is_signed = k[0] == 's', big_endian = k.ends_with("be");
      const int bytes = k.find("8") != std::string_view::npos ? 1 : k.find("16") != std::string_view::npos ? 2 : 4;
      const double lo = is_signed ? -std::ldexp(1.0, 8 * bytes - 1) : 0;
      const double hi = is_signed ? std::ldexp(1.0, 8 * bytes - 1) - 1 : std::ldexp(1.0, 8 * bytes) - 1;
      Token next_token = peek();
      if (next_token.is(")") || next_token.is(",")) continue;
      const Numeric n = parse_expression();
      for (int i = 0; i < n.terms; ++i) {
        const double x = std::isnan(n.v[i]) ? 0 : n.v[i] <= lo ? lo : n.v[i] >= hi ? hi : std::floor(n.v[i] + 0.5);
        const auto bits = static_cast<std::uint32_t>(static_cast<std::int64_t>(x));
        for (int b = 0; b < bytes; ++b) {
          const int shift = (big_endian ? bytes - 1 - b : b) * 8;
          out.put(static_cast<char>((bits >> shift) & 0xff));
        }
      }
      continue;
    }
    if (starts_string(t)) {
      unget(t);
      out << parse_string();
      continue;
    }
    unget(t);
    const Numeric n = parse_expression();
    if (n.terms == 1) {
      out << format_g(n.v[0]);
    } else {
      out << '<';
      for (int i = 0; i < n.terms; ++i) out << (i ? "," : "") << format_g(n.v[i]);
      out << "> ";
    }
  }
  out.flush();
  if (!out) fail_at(id, "cannot write to the user file \"" + file->name + "\"");
  (void)at;
}

}  // namespace povtrace::sdl

// Expressions (povray-sdl-and-geometry.md §5): two levels (parameter level = additive; full level with
// comparisons, & | and ?: inside parentheses and conditions), term counts with promotion, colour forms,
// built-in functions.
#include <cmath>
#include <algorithm>
#include <cstdio>
#include <ctime>
#include <functional>
#include <map>

#include "parser/expressions/int_cast.hpp"
#include "parser/expressions/numeric_ops.hpp"
#include "parser/expressions/expression_parser.hpp"
#include "parser/expressions/expression_programs.hpp"
#include "parser/interpreter.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {


double ExpressionParser::to_float(const Numeric& n, const Token& at) const {
  if (n.terms != 1) fail_at(at, "expected a float, found a " + value_type_name(Value(n)));
  return n.v[0];
}

// The first token of an expression, for its error messages: where the token ahead is plain it is made only if
// an error needs it (peek() would make it, and push it back, for every expression).
class ExpressionParser::ExpressionStart {
 public:
  explicit ExpressionStart(ExpressionParser& in) : in_(in), tokens_(nullptr), kept_(in.plain_ahead()) {
    if (kept_) tokens_ = in.token_stream().frame().tokens;
    else token_ = in.peek();
  }
  Token token() const { return kept_ ? in_.make_token(*tokens_, *kept_) : token_; }

 private:
  ExpressionParser& in_;
  const FileTokens* tokens_;
  const LexedToken* kept_;   // chunked storage: stays where it is while the expression is read
  Token token_;
};

double ExpressionParser::parse_float() {
  const ExpressionStart start(*this);
  const Numeric n = parse_additive();
  return n.terms == 1 ? n.v[0] : to_float(n, start.token());
}

double ExpressionParser::parse_float_full() {
  const ExpressionStart start(*this);
  const Numeric n = parse_expression();
  return n.terms == 1 ? n.v[0] : to_float(n, start.token());
}

Vec3 ExpressionParser::parse_vector() {
  const ExpressionStart start(*this);
  Numeric n = parse_additive();
  if (n.terms > 3 && !n.colour)
    fail_at(start.token(), "expected a 3-D vector, found a " + value_type_name(Value(n)));
  return promoted_to(n, 3).as_vec3();
}

// Parse_UV_Vect: a float or a 2-D vector at the parameter level.
std::pair<double, double> ExpressionParser::parse_uv_vector(std::string_view context) {
  const Token start = peek();
  const Numeric n = parse_additive();
  if (n.terms > 2)
    fail_at(start, "expected a 2-D vector " + std::string(context) + ", found a " + value_type_name(Value(n)));
  return {n.v[0], n.terms == 1 ? n.v[0] : n.v[1]};
}

// POV-Ray's Allow_Float: a float expression if one follows (`metallic`, `fresnel on`, `metallic 0.5`), else the
// default. A keyword that is an item of the enclosing block (`metallic falloff 2`) is no float.
double ExpressionParser::optional_float(double fallback) {
  const Token n = peek();
  static const std::string_view float_words[] = {"true", "false", "on", "off", "yes", "no", "pi", "version",
                                                 "clock", "clock_delta", "clock_on"};
  bool starts = n.kind == TokenKind::number || n.is("(") || n.is("-") || n.is("+") || n.is("!");
  if (n.kind == TokenKind::identifier) {
    if (!is_reserved_word(n.text)) {
      const Value* v = lookup(n);
      starts = v && std::holds_alternative<Numeric>(*v);
    } else {
      for (auto w : float_words) starts = starts || n.text == w;
      starts = starts || is_float_function(n.text);
    }
  }
  return starts ? parse_float() : fallback;
}

// ---- full level ----------------------------------------------------------------------------------------
Numeric ExpressionParser::compare_strings() {
  const std::string a = parse_string();
  Token op = next();
  static const std::string_view ops[] = {"<", "<=", "=", "!=", ">=", ">"};
  if (op.kind != TokenKind::symbol || std::find(std::begin(ops), std::end(ops), op.text) == std::end(ops))
    fail_expected(op, "a comparison operator (<, <=, =, !=, >=, >) after a string");
  const int c = strcmp_value(a, parse_string());
  const bool r = op.is("<") ? c < 0 : op.is("<=") ? c <= 0 : op.is("=") ? c == 0 : op.is("!=") ? c != 0
                 : op.is(">=") ? c >= 0 : c > 0;
  return Numeric::scalar(r ? 1.0 : 0.0);
}

int ExpressionParser::strcmp_value(const std::string& a, const std::string& b) {
  // POV-Ray's UCS2_strcmp: the difference of the first differing characters (0 past the end).
  for (std::size_t i = 0;; ++i) {
    const int ca = i < a.size() ? static_cast<unsigned char>(a[i]) : 0;
    const int cb = i < b.size() ? static_cast<unsigned char>(b[i]) : 0;
    if (ca != cb || ca == 0) return ca - cb;
  }
}

// datetime(F [, format]) (§5): F days since 2000-01-01 00:00 UTC, formatted with strftime in UTC; the default
// format is "%Y-%m-%d %H:%M:%SZ".
std::string ExpressionParser::parse_datetime() {
  expect("(", " after 'datetime'");
  const double days = parse_float();
  accept(",");
  std::string format = "%Y-%m-%d %H:%M:%SZ";
  Token t = next();
  if (!t.is(")")) {
    unget(t);
    Token at = peek();
    format = parse_string();
    if (format.empty()) fail_at(at, "datetime() needs a non-empty format string");
    if (format.size() > 200) fail_at(at, "the datetime() format string is longer than 200 characters");
    expect(")", " closing datetime()");
  }
  const double seconds = std::floor((days + (365 * 30 + 7)) * 86400.0 + 0.5);
  if (!(std::fabs(seconds) < 1e15)) fail_at(t, "datetime() of a date out of range");
  const std::time_t stamp = static_cast<std::time_t>(seconds);
  std::tm tm{};
  if (!gmtime_r(&stamp, &tm)) fail_at(t, "datetime() of a date out of range");
  char buf[201];
  const std::size_t n = std::strftime(buf, sizeof buf, format.c_str(), &tm);
  return std::string(buf, n);
}

// One out-of-line call per expression: a find inline and a run out of line cost more (expression_programs.hpp).
inline bool ExpressionParser::run_expression_program(bool full, Numeric& out) {
  return in().programs_.run(full, out, nesting());
}

Numeric ExpressionParser::parse_expression() {
  if (Numeric n; run_expression_program(true, n)) return n;
  auto comparison = [this]() {
    // A string operand takes exactly one comparison with another string, in strcmp order (§5).
    if (string_ahead()) return compare_strings();
    Numeric left = parse_additive();
    while (true) {
      const auto ahead = raw_ahead();
      const Comparison c = comparison_of(ahead.kind, ahead.text);
      if (c == Comparison::none) return left;
      const Token op = next();
      Numeric right = parse_additive();
      left = Numeric::scalar(compare(c, to_float(left, op), to_float(right, op)) ? 1.0 : 0.0);
    }
  };
  Numeric value = comparison();
  while (true) {   // & and | share one level (§5: (1 | 0 & 0) = 0)
    if (const auto look = raw_ahead(); !look.is("&") && !look.is("|")) break;
    const Token op = next();
    const bool a = std::fabs(to_float(value, op)) > kEqualEpsilon;
    const bool b = std::fabs(to_float(comparison(), op)) > kEqualEpsilon;
    value = Numeric::scalar((op.is("&") ? (a && b) : (a || b)) ? 1.0 : 0.0);
  }
  if (!raw_ahead().is("?")) return value;
  const Token q = next();
  // `c ? a : c ? a : …` recurses here without passing parse_unary's guard at each level.
  const NestingGuard guard(*this, q);
  const bool c = std::fabs(to_float(value, q)) > kEqualEpsilon;
  Numeric a = parse_expression();
  expect(":", " in the conditional expression c ? a : b");
  Numeric b = parse_expression();
  return c ? a : b;
}

// ---- parameter level -------------------------------------------------------------------------------------
// After a complete operand the look for an operator is raw (peek_raw): as in POV-Ray, a directive or macro call
// there runs only once the value is finished — e.g. the next `#declare` after a value without ';' (§1 item 6).
Numeric ExpressionParser::parse_additive() {
  if (Numeric n; run_expression_program(false, n)) return n;
  return parse_additive_rest(parse_multiplicative());
}

Numeric ExpressionParser::parse_additive_after(Numeric first_operand) {
  return parse_additive_rest(parse_multiplicative_rest(parse_postfix(first_operand)));
}

Numeric ExpressionParser::parse_additive_rest(Numeric value) {
  while (true) {
    const auto op = raw_ahead();   // no Token made: most operands are followed by no operator
    const bool plus = op.is("+");
    if (!plus && !op.is("-")) return value;
    skip_ahead();
    if (plus) value = componentwise(value, parse_multiplicative(), std::plus<>());
    else value = componentwise(value, parse_multiplicative(), std::minus<>());
  }
}

Numeric ExpressionParser::parse_multiplicative() { return parse_multiplicative_rest(parse_unary()); }

Numeric ExpressionParser::parse_multiplicative_rest(Numeric value) {
  while (true) {
    const auto look = raw_ahead();
    const bool times = look.is("*");
    if (!times && !look.is("/")) return value;
    if (times) {
      skip_ahead();
      value = componentwise(value, parse_unary(), std::multiplies<>());
    } else {
      const Token op = next();   // its location, should the divisor be zero
      Numeric divisor = parse_unary();
      promote(value, divisor);
      for (int i = 0; i < value.terms; ++i) {
        if (divisor.v[i] == 0.0) warn(op.loc, "division by zero");
        value.v[i] /= divisor.v[i];
      }
    }
  }
}

Numeric ExpressionParser::parse_unary() {
  if (Numeric n; fast_operand(n)) return n;
  // A parenthesis from the kept tokens, as parse_primary takes it, without making its Token: what a macro body
  // such as `(A + B * 0.001)` starts with (its expression program cannot end at the body's #end).
  if (!in().token_limit_ && nesting_room() && plain_symbol(plain_ahead(), '(')) {
    consume_plain();
    const NestingGuard guard(*this, NestingGuard::RoomChecked{});
    Numeric n = parse_expression();
    skip_expected(')', " closing the parenthesis");
    return parse_postfix(n);
  }
  const Token t = next();
  const NestingGuard guard(*this, t);   // every nested operand passes through here
  if (t.kind != TokenKind::symbol) return parse_postfix(parse_primary(t));
  if (t.is("-")) {
    Numeric n = parse_unary();
    for (int i = 0; i < n.terms; ++i) n.v[i] = -n.v[i];
    return n;
  }
  if (t.is("+")) return parse_unary();
  if (t.is("!")) {
    Numeric n = parse_unary();
    for (int i = 0; i < n.terms; ++i) n.v[i] = std::fabs(n.v[i]) <= kEqualEpsilon ? 1.0 : 0.0;
    return n;
  }
  return parse_postfix(parse_primary(t));
}

// .x .y .z .u .v .t .red .green .blue .filter .transmit .gray (§5 item 7).
Numeric ExpressionParser::parse_postfix(Numeric value) {
  while (true) {
    if (!raw_ahead().is(".")) return value;
    next();
    Token member = next();
    static const std::map<std::string_view, int> components = {
        {"x", 0}, {"u", 0}, {"red", 0}, {"y", 1}, {"v", 1}, {"green", 1}, {"z", 2}, {"blue", 2},
        {"t", 3}, {"filter", 3}, {"transmit", 4}, {"gray", -1}, {"grey", -1}};
    auto it = member.kind == TokenKind::identifier ? components.find(member.text) : components.end();
    if (it == components.end()) fail_expected(member, "a component name (x, y, z, t, red, green, blue, filter, "
                                                      "transmit, gray) after '.'");
    if (it->second < 0) {
      value = Numeric::scalar(0.297 * value.v[0] + 0.589 * value.v[1] + 0.114 * value.v[2]);
      continue;
    }
    if (it->second >= value.terms)
      fail_at(member, "'." + std::string(member.text) + "' selects a component that this " +
                          value_type_name(Value(value)) + " does not have");
    value = Numeric::scalar(value.v[it->second]);
  }
}

Numeric ExpressionParser::parse_vector_literal(const Token& open) {
  Numeric n;
  n.terms = 0;
  do {
    if (n.terms == 5) fail_at(open, "a vector has at most 5 components");
    n.v[n.terms++] = parse_float();
    // The separator: a plain ',' or '>' is taken where it stands (no Token made, none pushed back).
    if (const LexedToken* k = plain_ahead(); plain_symbol(k, '>')) {
      consume_plain();
      break;
    } else if (plain_symbol(k, ',')) {
      consume_plain();
      if (plain_symbol(plain_ahead(), '>')) { consume_plain(); break; }
      if (!plain_ahead() && peek().is(">")) { next(); break; }
      continue;
    } else if (k) {
      continue;   // commas between components are optional (§5)
    }
    Token sep = next();
    if (sep.is(">")) break;
    if (!sep.is(",")) unget(sep);   // commas between components are optional (§5)
    else if (peek().is(">")) { next(); break; }   // a trailing comma before '>' is accepted, as POV-Ray does
  } while (true);
  if (n.terms < 2) fail_at(open, "a vector needs 2 to 5 components");
  return n;
}

// srgb… colours (§5): the components are sRGB-encoded; they are decoded to linear light, then encoded with the
// working gamma (assumed_gamma; 1 when not set). Filter and transmit are taken as they are.
namespace {
double srgb_to_working(double encoded, double gamma) {
  const double linear = encoded <= 0.04045 ? encoded / 12.92 : std::pow((encoded + 0.055) / 1.055, 2.4);
  return gamma == 1.0 || linear <= 0 ? linear : std::pow(linear, 1.0 / gamma);
}
}  // namespace

// rgb, rgbf, rgbt, rgbft: the expression after the keyword is a full expression promoted to the stated count
// (§5 "Colours"), then placed in the five colour channels.
Numeric ExpressionParser::parse_colour_keyword_form(const Token& keyword) {
  const bool srgb = keyword.text.starts_with("srgb");
  const std::string_view k = srgb ? keyword.text.substr(1) : keyword.text;   // srgbf → the rgbf layout
  Token start = peek();
  Numeric e = parse_expression();
  const int count = k == "rgb" ? 3 : (k == "rgbft" ? 5 : 4);
  if (e.terms > count && !e.colour)
    fail_at(start, "'" + std::string(k) + "' takes " + std::to_string(count) + " components, found " +
                       std::to_string(e.terms));
  e = promoted_to(e, count);
  Numeric c;
  c.terms = 5;
  c.colour = true;
  const double gamma = assumed_gamma().value_or(1.0);
  for (int i = 0; i < 3; ++i) c.v[i] = srgb ? srgb_to_working(e.v[i], gamma) : e.v[i];
  if (k == "rgbf") c.v[3] = e.v[3];
  if (k == "rgbt") c.v[4] = e.v[3];
  if (k == "rgbft") { c.v[3] = e.v[3]; c.v[4] = e.v[4]; }
  return c;
}


bool ExpressionParser::starts_colour(const Token& t) const {
  if (t.kind != TokenKind::identifier) return false;
  static const std::string_view words[] = {"color", "colour", "rgb", "rgbf", "rgbt", "rgbft", "red", "green",
                                           "blue", "filter", "transmit", "srgb", "srgbf", "srgbt", "srgbft"};
  for (auto w : words)
    if (t.text == w) return true;
  if (reserved(t)) return false;
  const Value* v = lookup(t);
  return v && std::holds_alternative<Numeric>(*v) && std::get<Numeric>(*v).colour;
}

// Parse_Colour: [color|colour] then rgb… form, colour id or expression, then overrides red/green/blue/
// filter/transmit. A bare expression fills all five channels (`color 0.5` sets f and t too, §5).
Colour ExpressionParser::parse_colour() {
  Numeric c;
  c.terms = 5;
  c.colour = true;
  bool have_base = false;
  Token t = next();
  if (t.is("color") || t.is("colour")) t = next();
  while (true) {
    const std::string_view k = t.kind == TokenKind::identifier ? t.text : std::string_view();
    if (!have_base && (k == "rgb" || k == "rgbf" || k == "rgbt" || k == "rgbft" || k.starts_with("srgb"))) {
      c = parse_colour_keyword_form(t);
      have_base = true;
    } else if (k == "red" || k == "green" || k == "blue" || k == "filter" || k == "transmit") {
      const int channel = k == "red" ? 0 : k == "green" ? 1 : k == "blue" ? 2 : k == "filter" ? 3 : 4;
      c.v[channel] = parse_float();
      have_base = true;
    } else if (!have_base && t.kind != TokenKind::end_of_input && !t.is("}") &&
               !(k == "rgb" || k == "rgbf" || k == "rgbt" || k == "rgbft")) {
      unget(t);
      Token start = peek();
      Numeric e = parse_additive();
      if (e.terms > 5) fail_at(start, "a colour has at most 5 components");
      if (e.terms == 1) e = promoted_to(e, 5);
      for (int i = 0; i < 5; ++i) c.v[i] = i < e.terms ? e.v[i] : 0.0;
      have_base = true;
    } else {
      unget(t);
      break;
    }
    // Only overrides can follow a complete colour; look raw, as after any operand.
    const Token after = peek_raw();
    if (!(after.is("red") || after.is("green") || after.is("blue") || after.is("filter") || after.is("transmit")))
      break;
    t = next();
  }
  if (!have_base) fail_expected(peek(), "a colour (rgb <r,g,b>, a colour identifier or an expression)");
  return c.stored().as_colour();
}

bool ExpressionParser::string_ahead() {
  const LexedToken* k = plain_ahead();
  if (!k) return starts_string(peek());
  if (k->kind() != TokenKind::identifier) return k->kind() == TokenKind::string;
  // starts_string() of the token it would make, from its NameId (asked before every comparison operand).
  if (is_string_function(text_of(*k))) return true;
  if (symbol_table().is_reserved(k->payload)) return false;
  const Value* v = symbol_table().find(k->payload);
  return v && std::holds_alternative<std::string>(*v);
}

bool ExpressionParser::starts_string(const Token& t) const {
  if (t.kind == TokenKind::string) return true;
  if (t.kind != TokenKind::identifier) return false;
  if (is_string_function(t.text)) return true;
  if (reserved(t)) return false;
  const Value* v = lookup(t);
  return v && std::holds_alternative<std::string>(*v);
}

namespace {
std::string format_str(double value, int width, int precision) {
  // str(F, L, P) (§5): L > 0 space-padded width, L < 0 zero-padded width |L|, P < 0 the default 6 decimals.
  if (precision < 0) precision = 6;
  // The text is cut at 511 characters anyway; larger widths and precisions only made snprintf fail (a width of
  // 2^31) or allocate gigabytes (a precision of 2·10^9).
  constexpr int kLimit = 4096;
  width = std::clamp(width, -kLimit, kLimit);
  precision = std::min(precision, kLimit);
  char buf[512];
  if (width < 0) std::snprintf(buf, sizeof buf, "%0*.*f", -width, precision, value);
  else std::snprintf(buf, sizeof buf, "%*.*f", width, precision, value);
  return buf;
}
}  // namespace

std::string ExpressionParser::parse_string() {
  Token t = next();
  const NestingGuard guard(*this, t);   // concat(concat(…)), strupr(strlwr(…)) nest without an expression level
  if (t.kind == TokenKind::string) return string_value(t, file_of(t.loc), true);
  if (const Value* v = lookup(t)) {
    if (std::holds_alternative<std::string>(*v)) return std::get<std::string>(*v);
  }
  if (t.is("concat")) {
    expect("(", " after concat");
    std::string s = parse_string();
    // Commas between the strings are optional, as everywhere POV-Ray reads arguments.
    while (true) {
      const bool comma = accept(",");
      if (!comma && !starts_string(peek())) break;
      s += parse_string();
    }
    expect(")", " closing concat(...)");
    return s;
  }
  if (t.is("str")) {
    expect("(", " after str");
    const double value = parse_float();
    accept(",");
    const double width = parse_float();
    accept(",");
    const double precision = parse_float();
    expect(")", " closing str(...)");
    return format_str(value, saturating_cast<int>(width), saturating_cast<int>(precision));
  }
  if (t.is("chr")) {
    expect("(", " after chr");
    const double code = parse_float();
    expect(")", " closing chr(...)");
    return std::string(1, static_cast<char>(saturating_cast<int>(code) & 0x7f));
  }
  if (t.is("vstr")) {
    expect("(", " after vstr");
    const int n = std::clamp(saturating_cast<int>(parse_float()), 2, 5);
    accept(",");
    // Not promoted as in arithmetic: POV-Ray prints a float F as F, 0, 0… (vstr(3, 5, …) is "5,0,0"), and
    // zero-pads a shorter vector.
    Numeric v = parse_additive();
    for (int i = v.terms; i < 5; ++i) v.v[i] = 0;
    accept(",");
    const std::string sep = parse_string();
    accept(",");
    const int width = saturating_cast<int>(parse_float());
    accept(",");
    const int precision = saturating_cast<int>(parse_float());
    expect(")", " closing vstr(...)");
    std::string s;
    for (int i = 0; i < n; ++i) s += (i ? sep : "") + format_str(v.v[i], width, precision);
    return s;
  }
  if (t.is("strupr") || t.is("strlwr")) {
    expect("(", "");
    std::string s = parse_string();
    expect(")", "");
    for (char& c : s) {
      const int byte = static_cast<unsigned char>(c);   // toupper/tolower of a negative char is undefined
      c = static_cast<char>(t.is("strupr") ? std::toupper(byte) : std::tolower(byte));
    }
    return s;
  }
  if (t.is("datetime")) return parse_datetime();
  if (t.is("substr")) {
    expect("(", " after substr");
    std::string s = parse_string();
    accept(",");
    const int start = saturating_cast<int>(parse_float());
    accept(",");
    const int len = saturating_cast<int>(parse_float());
    expect(")", " closing substr(...)");
    if (start < 1 || len < 0 || static_cast<long long>(start) - 1 + len > static_cast<long long>(s.size()))
      fail_at(t, "substr(…, " + std::to_string(start) + ", " + std::to_string(len) + ") is out of range");
    return s.substr(static_cast<std::size_t>(start - 1), static_cast<std::size_t>(len));
  }
  fail_expected(t, "a string");
}

}  // namespace povtrace::sdl


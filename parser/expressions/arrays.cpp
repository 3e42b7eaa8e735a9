// Arrays (povray-sdl-and-geometry.md §3, §4, §5): `array[N][M]… [{ initialisers }]`, element reads `A[i][j]`
// (resolved where the name is read, token_stream.cpp: process_identifier), element assignment
// `#declare A[i] = …`, `defined(A[i])` / `#ifdef (A[i])`, dimensions() and dimension_size().
#include <cmath>
#include <cstdio>

#include "parser/expressions/array_values.hpp"
#include "parser/interpreter.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
constexpr double kSubscriptEpsilon = 1e-10;   // POV-Ray truncates (int)(value + 1e-10)
constexpr std::size_t kMaxDimensions = 5;
// Every element slot holds a whole Value (a few hundred bytes): beyond this many elements (about 1.5 GB) an
// array is refused cleanly instead of exhausting memory. The sample scenes' largest arrays hold ~10^4 elements.
constexpr double kMaxElements = 1 << 22;

std::string number_text(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%g", v);
  return buf;
}

std::string plural_type(const std::string& type) { return type + "s"; }
}  // namespace

Value ArrayValues::parse_array_declaration(const Token& keyword) {
  auto a = std::make_shared<ArrayValue>();
  double total = 1;
  // Raw looks: the value may be complete after any `]` or `}`, and a following directive must run only after it
  // is stored (§1 item 6).
  while (peek_raw().is("[")) {
    Token open = next();
    if (a->sizes.size() == kMaxDimensions) fail_at(open, "an array has at most 5 dimensions");
    Token at = peek();
    const double size = parse_float();
    expect("]", " closing the array dimension");
    const double n = std::trunc(size + kSubscriptEpsilon);
    if (!(n >= 1)) fail_at(at, "an array dimension must be at least 1, found " + number_text(size));
    total *= n;
    if (total > kMaxElements)
      fail_at(at, "this array would have more than " + std::to_string(static_cast<long>(kMaxElements)) +
                      " elements, povtrace's limit");
    a->sizes.push_back(static_cast<std::size_t>(n));
  }
  if (a->sizes.empty()) fail_expected(peek(), "'[' and a dimension size after 'array'");
  a->elements.resize(static_cast<std::size_t>(total));
  if (peek_raw().is("{")) parse_array_initialiser(*a, 0, 0);
  (void)keyword;
  return Value(std::move(a));
}

// { … } for dimension `dim`: nested blocks down to the last dimension, whose block holds exactly that many values
// (commas optional).
void ArrayValues::parse_array_initialiser(ArrayValue& a, std::size_t dim, std::size_t base) {
  const NestingGuard guard(*this, peek());
  Token open = expect("{", " opening the array initialiser");
  std::size_t stride = 1;
  for (std::size_t d = dim + 1; d < a.sizes.size(); ++d) stride *= a.sizes[d];
  const std::size_t count = a.sizes[dim];
  for (std::size_t i = 0; i < count; ++i) {
    if (dim + 1 < a.sizes.size()) {
      if (peek().is("}"))
        fail_at(peek(), "too few initialisers: dimension " + std::to_string(dim + 1) + " of this array has size " +
                            std::to_string(count) + ", found " + std::to_string(i));
      parse_array_initialiser(a, dim + 1, base + i * stride);
      continue;
    }
    Token first = next();
    if (first.is("}"))
      fail_at(first, "too few initialisers: dimension " + std::to_string(dim + 1) + " of this array has size " +
                         std::to_string(count) + ", found " + std::to_string(i));
    std::optional<Value> value;
    {
      const RawOperatorLook raw_look(*this);   // as in POV-Ray, whose Ok_To_Declare is off in an initialiser
      value = try_parse_rvalue(first);
    }
    if (!value) fail_expected(first, "a value in the array initialiser");
    store_element(a, base + i, std::move(*value), first, "this array");
    accept(",");
  }
  Token close = next();
  if (!close.is("}"))
    fail_expected(close, "'}' closing the array initialiser opened at " + open.loc.to_string() + " (dimension " +
                             std::to_string(dim + 1) + " has size " + std::to_string(count) + ")");
  if (peek_raw().is(",")) next();
}

// The first value stored fixes the array's element type; a value of another type is an error (§3, [V sdl_eps]).
void ArrayValues::store_element(ArrayValue& a, std::size_t index, Value value, const Token& at,
                                const std::string& name) {
  const std::string type = array_type_of(value);
  if (a.type.empty()) a.type = type;
  else if (type != a.type)
    fail_at(at, "cannot store a " + type + " in " + name + ", an array of " + plural_type(a.type) +
                    " (the first value stored fixes the element type)");
  a.elements[index] = std::move(value);
}

std::size_t ArrayValues::parse_subscripts(const ArrayValue& a, const std::string& name, Token& last) {
  std::size_t index = 0;
  for (std::size_t d = 0; d < a.sizes.size(); ++d) {
    Token open = next();
    if (!open.is("["))
      fail_expected(open, "'[' : " + name + " has " + std::to_string(a.sizes.size()) +
                              " dimensions and takes as many subscripts");
    Token at = peek();
    const double v = parse_float();
    last = expect("]", " closing the array subscript");
    if (v < -kSubscriptEpsilon) fail_at(at, "negative subscript " + number_text(v) + " for " + name);
    const double k = std::trunc(v + kSubscriptEpsilon);
    if (!(k < static_cast<double>(a.sizes[d])))   // also NaN
      fail_at(at, "subscript " + number_text(k) + " is out of range for " + name + " (dimension " +
                      std::to_string(d + 1) + " has size " + std::to_string(a.sizes[d]) + ": 0 to " +
                      std::to_string(a.sizes[d] - 1) + ")");
    index = index * a.sizes[d] + static_cast<std::size_t>(k);
  }
  return index;
}

std::optional<ArrayValues::ElementRef> ArrayValues::parse_element_reference(const Token& name) {
  if (name.kind != TokenKind::identifier || is_reserved_word(name.text)) return std::nullopt;
  const Value* v = symbols_.find(std::string(name.text));
  if (!v || !std::holds_alternative<std::shared_ptr<ArrayValue>>(*v)) return std::nullopt;
  ElementRef ref{std::get<std::shared_ptr<ArrayValue>>(*v), 0};
  std::string shown(name.text);
  while (true) {
    Token last = name;
    ref.index = parse_subscripts(*ref.array, shown, last);
    if (last.loc.file == name.loc.file && last.end.offset > name.begin.offset)
      shown = std::string(name.text.data(), last.end.offset - name.begin.offset);
    // An element that is itself an array takes further subscripts.
    const auto& e = ref.array->elements[ref.index];
    const bool more = ahead_is("[");
    if (!more || !e || !std::holds_alternative<std::shared_ptr<ArrayValue>>(*e)) return ref;
    ref.array = std::get<std::shared_ptr<ArrayValue>>(*e);
  }
}

// #declare A[i]… = value / #local A[i]… = value: assigns the element of the visible array in place.
void ArrayValues::directive_declare_element(const Token& name, bool local) {
  auto ref = parse_element_reference(name);
  const std::string shown(name.text);
  Token eq = next();
  if (!eq.is("=")) fail_expected(eq, "'=' after #" + std::string(local ? "local " : "declare ") + shown + "[…]");
  Token first = next();
  std::optional<Value> value;
  {
    const RawOperatorLook raw_look(*this);   // the value of a #declare
    value = try_parse_rvalue(first);
  }
  if (!value) fail_expected(first, "a value for an element of " + shown);
  const bool needs_semicolon = std::holds_alternative<Numeric>(*value) && language_version() >= 350;
  // POV-Ray stores `#local A[i] = …` of an array that is not in the innermost table (a global array, from inside
  // a macro or an include file) in a new local entry nothing can read: the array stays unchanged.
  if (local && symbols_.level_of(shown) != symbols_.depth() - 1)
    warn(name.loc, "#local of an element of '" + shown + "', an array declared outside this macro or file, has "
                   "no effect (as in POV-Ray); #declare assigns it");
  else
    store_element(*ref->array, ref->index, std::move(*value), first, shown);
  Token semi = peek_raw();
  if (semi.is(";")) next();
  else if (needs_semicolon) fail_expected(semi, "';' after the value of " + shown + "[…]");
}

bool ArrayValues::parse_defined_identifier() {
  Token name = raw();
  if (name.kind != TokenKind::identifier) fail_expected(name, "an identifier");
  bool defined = false;
  if (!is_reserved_word(name.text)) {
    const Value* v = symbols_.find(std::string(name.text));
    defined = v != nullptr;
    const bool subscripted = ahead_is("[");
    if (v && subscripted) {
      auto ref = parse_element_reference(name);
      if (ref) defined = ref->array->elements[ref->index].has_value();
    }
  }
  expect(")", " after the identifier");
  return defined;
}

// dimensions(A): the number of dimensions; dimension_size(A, k): the size of dimension k (1-based), 0 when k is
// out of range (§5).
Numeric ArrayValues::parse_dimensions(const Token& name) {
  expect("(", " after '" + std::string(name.text) + "'");
  Token id = next();
  const Value* v = lookup(id);
  if (!v || !std::holds_alternative<std::shared_ptr<ArrayValue>>(*v))
    fail_expected(id, "an array identifier in " + std::string(name.text) + "()");
  const ArrayValue& a = *std::get<std::shared_ptr<ArrayValue>>(*v);
  if (name.is("dimensions")) {
    expect(")", " closing dimensions()");
    return Numeric::scalar(static_cast<double>(a.sizes.size()));
  }
  accept(",");
  const double k = std::trunc(parse_float()) - 1;
  expect(")", " closing dimension_size()");
  if (!(k >= 0 && k < static_cast<double>(a.sizes.size()))) return Numeric::scalar(0);   // also NaN
  return Numeric::scalar(static_cast<double>(a.sizes[static_cast<std::size_t>(k)]));
}

}  // namespace povtrace::sdl

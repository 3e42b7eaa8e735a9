// The `function { … }` sub-language (povray-sdl-and-geometry.md §6): parsing a definition into an expression tree,
// folding it as POV-Ray 3.7's function compiler does, compiling it for the evaluator (function_vm.cpp), and the
// interpreter's hooks: `#declare F = function …`, calls `F(a, b, c)` in SDL expressions, and the rule that a
// function must be #undef'd before its name is declared again.
//
// Grammar of a body, lowest precedence first (POV-Ray's fnsyntax.cpp): `|`; `&`; `= != < <= > >=`; `+ -`; `* /`;
// one optional sign; operands: numbers, `pi`, `clock`, declared floats (captured as constants now), parameters
// and x y z u v, built-in functions, declared functions, `( … )`, and vector-function calls followed by a
// member (`F(x,y,z).x`). There is no `?:`, `!` or `^`, and no second sign (`--x` is an error, as in POV-Ray).
//
// Folding follows POV-Ray so that values agree to the last bit: in a chain of operators of one precedence, two
// adjacent constant operands are combined (`x+1+2` is x+3; `*` and `/` only while no variable stands to their
// left); a constant divisor becomes a multiplication by its reciprocal; pow() by a constant 2…8 multiplies; a
// sign before a constant folds. Like POV-Ray, only the first argument of a call is folded, and a parenthesised
// expression is never a constant for the chain around it.
#include <algorithm>
#include <cmath>

#include "runtime/function_value.hpp"
#include "parser/expressions/function_values.hpp"
#include "parser/interpreter.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {

constexpr int kMaxParameters = 56;   // POV-Ray's MAX_PARAMETER_LIST

enum class Op : std::uint8_t { first, or_, and_, eq, ne, lt, le, gt, ge, add, sub, mul, div, pow };

enum class Builtin : std::uint8_t {
  math1,   // FnMath1 in `math`
  radians, degrees, sqr,
  math2,   // FnMath2 in `math`: atan2, mod, div
  pow, min, max, select, sum, prod
};

struct BuiltinInfo {
  std::string_view name;
  Builtin kind;
  int math = 0;
};

const BuiltinInfo* find_builtin(std::string_view name) {
  static const BuiltinInfo table[] = {
      {"sin", Builtin::math1, int(FnMath1::sin)},     {"cos", Builtin::math1, int(FnMath1::cos)},
      {"tan", Builtin::math1, int(FnMath1::tan)},     {"asin", Builtin::math1, int(FnMath1::asin)},
      {"acos", Builtin::math1, int(FnMath1::acos)},   {"atan", Builtin::math1, int(FnMath1::atan)},
      {"sinh", Builtin::math1, int(FnMath1::sinh)},   {"cosh", Builtin::math1, int(FnMath1::cosh)},
      {"tanh", Builtin::math1, int(FnMath1::tanh)},   {"asinh", Builtin::math1, int(FnMath1::asinh)},
      {"acosh", Builtin::math1, int(FnMath1::acosh)}, {"atanh", Builtin::math1, int(FnMath1::atanh)},
      {"floor", Builtin::math1, int(FnMath1::floor)}, {"ceil", Builtin::math1, int(FnMath1::ceil)},
      {"sqrt", Builtin::math1, int(FnMath1::sqrt)},   {"exp", Builtin::math1, int(FnMath1::exp)},
      {"ln", Builtin::math1, int(FnMath1::ln)},       {"log", Builtin::math1, int(FnMath1::log)},
      {"int", Builtin::math1, int(FnMath1::int_)},    {"abs", Builtin::math1, int(FnMath1::abs)},
      {"radians", Builtin::radians},                   {"degrees", Builtin::degrees},
      {"sqr", Builtin::sqr},                           {"atan2", Builtin::math2, int(FnMath2::atan2)},
      {"mod", Builtin::math2, int(FnMath2::mod)},     {"div", Builtin::math2, int(FnMath2::div)},
      {"pow", Builtin::pow},                           {"min", Builtin::min},
      {"max", Builtin::max},                           {"select", Builtin::select},
      {"sum", Builtin::sum},                           {"prod", Builtin::prod},
  };
  for (const auto& b : table)
    if (b.name == name) return &b;
  return nullptr;
}

// SDL built-ins that POV-Ray 3.7 does not accept inside a function body.
bool is_sdl_only_function(std::string_view name) {
  static const std::string_view names[] = {
      "bitwise_and", "bitwise_or", "bitwise_xor", "vlength", "vdot", "vcross", "vnormalize", "vrotate",
      "vaxis_rotate", "vturbulence", "strlen", "strcmp", "asc", "val", "file_exists", "defined", "seed", "rand",
      "dimensions", "dimension_size", "inside", "trace", "min_extent", "max_extent", "now", "true", "false",
      "yes", "no", "on", "off", "version", "clock_on", "clock_delta"};
  for (auto n : names)
    if (n == name) return true;
  return false;
}

struct ChainItem {
  Op op;
  int node;
  SourceLoc loc;   // the operator (for "division by zero")
};

struct Node {
  enum class Kind { constant, variable, group, chain, neg, builtin, call } kind = Kind::constant;
  double number = 0;                 // constant
  int slot = -1;                     // variable: frame slot; -1 for x/y/z/u/v without such a parameter (0)
  int child = -1;                    // group, neg
  std::vector<ChainItem> items;      // chain: operands with the operator before each (the first: Op::first)
  Builtin builtin = Builtin::math1;  // builtin
  int math = 0;
  std::vector<int> args;             // builtin, call: argument groups
  int local = -1;                    // sum/prod: its three frame slots (total, variable, end)
  std::shared_ptr<const FunctionValue> fn;   // call
  int member = 0;                    // call of a vector function: the component (function_vm.cpp)
  SourceLoc loc;
};

}  // namespace

// Parses one `function …` definition; a friend of the FunctionValues part, reading its tokens, textures and splines
// through it.
class FunctionParser {
 public:
  explicit FunctionParser(FunctionValues& in) : in_(in) {}
  std::shared_ptr<const FunctionValue> parse_definition(const Token& keyword);

 private:
  using Kind = Node::Kind;

  int add(Node n) {
    nodes_.push_back(std::move(n));
    return static_cast<int>(nodes_.size() - 1);
  }
  int constant(double v, const SourceLoc& loc) {
    Node n;
    n.number = v;
    n.loc = loc;
    return add(std::move(n));
  }
  int group(int child) {
    Node n;
    n.kind = Kind::group;
    n.child = child;
    n.loc = nodes_[static_cast<std::size_t>(child)].loc;
    return add(std::move(n));
  }

  void parse_parameters();
  int parse_body_expression();     // a full expression in a fresh group (POV-Ray's parse_expr)
  int parse_level(int level);
  int parse_signed_operand();
  int parse_operand();
  int parse_builtin(const Token& name, const BuiltinInfo& info);
  int parse_call(const Token& name, std::shared_ptr<const FunctionValue> fn);
  int variable(const Token& name);
  int component(const Token& member, const FunctionValue& fn, const Token& name);

  bool has_variable(int n) const;
  void optimise(int n);
  void optimise_chain(Node& chain);
  void compile(int n);
  void compile_chain(int n);
  void compile_builtin(int n);
  void compile_call(int n);
  void emit(FnOp op, int a = 0, int b = 0, double k = 0, int c = 0);
  int here() const { return static_cast<int>(out_->code.size()); }
  int callee_index(const std::shared_ptr<const FunctionValue>& fn);

  FunctionValues& in_;
  std::vector<Node> nodes_;
  std::vector<std::string> parameters_;
  struct Local {
    std::string name;
    int slot;
  };
  std::vector<Local> locals_;      // sum()/prod() variables in scope, innermost last
  int frame_size_ = 0;
  int depth_ = 0;                  // operand stack depth while compiling
  FunctionValue* out_ = nullptr;
};

std::shared_ptr<const FunctionValue> FunctionParser::parse_definition(const Token& keyword) {
  auto f = std::make_shared<FunctionValue>();
  out_ = f.get();
  f->loc = keyword.loc;
  Token t = in_.next();
  const bool has_parameters = t.is("(");
  if (has_parameters) {
    parse_parameters();
    t = in_.next();
  }
  if (!t.is("{")) in_.fail_expected(t, has_parameters ? "'{' starting the function body" : "'(' or '{' after 'function'");
  Token first = in_.next();
  const std::string_view k = first.kind == TokenKind::identifier ? first.text : std::string_view();
  auto no_parameters = [&](const char* what) {
    if (has_parameters)
      in_.fail_at(first, std::string("function parameters are not allowed for ") + what +
                             " functions (they take x, y, z)");
  };
  if (k == "internal") {
    in_.expect("(", " after 'internal'");
    Token number = in_.next();
    if (number.kind != TokenKind::number) in_.fail_expected(number, "the number of an internal function");
    if (!(number.number >= 0) || number.number >= kInternalFunctionCount)
      in_.fail_at(number, "function 'internal(" + std::string(number.text) + ")' does not exist (POV-Ray has "
                          "internal(0) to internal(" + std::to_string(kInternalFunctionCount - 1) + "))");
    in_.expect(")", " after the number of the internal function");
    f->kind = FunctionValue::Kind::internal;
    f->internal_id = static_cast<int>(number.number);
    f->parameter_count = internal_function_info(f->internal_id).parameter_count;
  } else if (k == "transform") {
    no_parameters("transform");
    f->kind = FunctionValue::Kind::transform;
    f->transform = in_.textures_.parse_transform_block(first);
    f->return_size = 3;
  } else if (k == "pigment") {
    no_parameters("pigment");
    f->kind = FunctionValue::Kind::pigment;
    const Pigment p = in_.textures_.parse_pigment_block(first, Pigment{});
    // A plain colour can be evaluated without the renderer's patterns; any other pigment is evaluated by the
    // renderer (POV-Ray's f_pigment: Compute_Pigment at the point, without an intersection).
    if (p.pattern == PatternKind::solid && !p.unsupported) f->colour = p.colour;
    else if (p.unsupported) f->refusal = p.unsupported;
    else if (const PatternEvaluator* evaluator = in_.pattern_evaluator()) {
      auto prepared = evaluator->prepare_pigment(p);
      if (auto* ready = std::get_if<std::shared_ptr<const PreparedPigment>>(&prepared)) f->prepared_pigment = *ready;
      else f->refusal = UnsupportedFeature{std::get<std::string>(prepared), first.loc};
    }
    f->pigment = std::make_shared<const Pigment>(p);
    f->return_size = 5;
  } else if (k == "spline") {
    // function { spline { … } }: a vector function of one parameter, the spline's t (POV-Ray's f_spline),
    // returning the spline's 2 to 5 components.
    no_parameters("spline");
    f->kind = FunctionValue::Kind::spline;
    f->spline = std::make_shared<const SplineValue>(in_.splines_.parse_block());
    f->parameter_count = 1;
    f->return_size = f->spline->terms;
  } else if (k == "pattern") {
    // function { pattern { PATTERN MODIFIERS } }: a float function of x, y, z (POV-Ray's Parse_PatternFunction,
    // f_pattern): the pattern's value after its warps and wave step. Its syntax is a pigment's without colours,
    // so it is read as a pigment; the renderer evaluates it (ParseOptions::pattern_evaluator).
    no_parameters("pattern");
    f->kind = FunctionValue::Kind::pattern;
    if (!in_.peek().is("{")) in_.fail_expected(in_.peek(), "'{' after 'pattern'");
    const Pigment p = in_.textures_.parse_pigment_block(first, Pigment{});
    f->pigment = std::make_shared<const Pigment>(p);
    if (p.unsupported) f->refusal = p.unsupported;
    else if (const PatternEvaluator* evaluator = in_.pattern_evaluator()) {
      auto prepared = evaluator->prepare(p);
      if (auto* ready = std::get_if<std::shared_ptr<const PreparedPattern>>(&prepared)) f->pattern = *ready;
      else f->refusal = UnsupportedFeature{std::get<std::string>(prepared), first.loc};
    }
  } else {
    in_.unget(first);
    if (parameters_.empty()) parameters_ = {"x", "y", "z"};
    frame_size_ = static_cast<int>(parameters_.size());
    f->parameter_count = frame_size_;
    const int root = parse_body_expression();
    optimise(root);
    compile(root);
    emit(FnOp::ret);
    f->frame_size = frame_size_;
  }
  Token close = in_.next();
  if (!close.is("}")) in_.fail_expected(close, "an operator or '}' closing the function");
  return f;
}

// `( name [,] name … )` after `function`: undeclared identifiers or x, y, z, u, v; commas are optional.
void FunctionParser::parse_parameters() {
  while (true) {
    Token p = in_.next();
    const bool axis = p.is("x") || p.is("y") || p.is("z") || p.is("u") || p.is("v");
    if (!axis && (p.kind != TokenKind::identifier || is_reserved_word(p.text) || in_.lookup(p)))
      in_.fail_expected(p, "a parameter name (an undeclared identifier, or x, y, z, u, v)");
    if (static_cast<int>(parameters_.size()) == kMaxParameters)
      in_.fail_at(p, "a function takes at most " + std::to_string(kMaxParameters) + " parameters");
    parameters_.emplace_back(p.text);
    if (in_.accept(",")) continue;   // a comma must be followed by another name: `function(a,)` is an error
    if (in_.accept(")")) return;
  }
}

int FunctionParser::parse_body_expression() {
  const int e = group(parse_level(0));
  Token end = in_.peek();
  if (!(end.is(")") || end.is("}") || end.is(",")))
    in_.fail_expected(end, "an operator (| & = != < <= > >= + - * /), ',', ')' or '}' in the function");
  return e;
}

// Levels 0 `|`, 1 `&`, 2 comparisons, 3 `+ -`, 4 `* /`; one chain node per level that has operators.
int FunctionParser::parse_level(int level) {
  if (level == 5) return parse_signed_operand();
  const int first = parse_level(level + 1);
  auto op_of = [level](const Token& t) -> std::optional<Op> {
    if (t.kind != TokenKind::symbol) return std::nullopt;
    const std::string_view s = t.text;
    switch (level) {
      case 0: if (s == "|") return Op::or_; break;
      case 1: if (s == "&") return Op::and_; break;
      case 2:
        if (s == "=") return Op::eq;
        if (s == "!=") return Op::ne;
        if (s == "<") return Op::lt;
        if (s == "<=") return Op::le;
        if (s == ">") return Op::gt;
        if (s == ">=") return Op::ge;
        break;
      case 3:
        if (s == "+") return Op::add;
        if (s == "-") return Op::sub;
        break;
      case 4:
        if (s == "*") return Op::mul;
        if (s == "/") return Op::div;
        break;
    }
    return std::nullopt;
  };
  Token t = in_.peek();
  std::optional<Op> op = op_of(t);
  if (!op) return first;
  Node chain;
  chain.kind = Kind::chain;
  chain.loc = nodes_[static_cast<std::size_t>(first)].loc;
  chain.items.push_back({Op::first, first, chain.loc});
  while (op) {
    in_.next();
    const int operand = parse_level(level + 1);
    chain.items.push_back({*op, operand, t.loc});
    t = in_.peek();
    op = op_of(t);
  }
  return add(std::move(chain));
}

int FunctionParser::parse_signed_operand() {
  Token t = in_.next();
  if (t.is("+")) return parse_operand();
  if (t.is("-")) {
    Node n;
    n.kind = Kind::neg;
    n.loc = t.loc;
    n.child = parse_operand();
    return add(std::move(n));
  }
  in_.unget(t);
  return parse_operand();
}

int FunctionParser::parse_operand() {
  Token t = in_.next();
  const FunctionValues::NestingGuard guard(in_, t);
  if (t.kind == TokenKind::number) return constant(t.number, t.loc);
  if (t.is("(")) {
    const int g = parse_body_expression();
    in_.expect(")", " closing the parenthesis");
    return g;
  }
  const char* const expected = "an operand (a number, a parameter, a float identifier, a function call or '(')";
  if (t.kind != TokenKind::identifier) in_.fail_expected(t, expected);
  const std::string_view w = t.text;
  if (is_reserved_word(w)) {
    if (w == "x" || w == "y" || w == "z" || w == "u" || w == "v") return variable(t);
    if (w == "pi") return constant(M_PI, t.loc);
    if (w == "clock") return constant(in_.clock(), t.loc);   // the frame's clock, as in SDL expressions
    if (const BuiltinInfo* b = find_builtin(w)) return parse_builtin(t, *b);
    if (w == "internal")
      in_.fail_at(t, "'internal(N)' must be the whole body of a function: function { internal(N) }");
    if (is_sdl_only_function(w))
      in_.fail_at(t, "'" + std::string(w) + "' cannot be used inside a function (POV-Ray's function language has "
                     "only sin … atanh, abs, sqrt, exp, ln, log, pow, int, floor, ceil, div, mod, min, max, "
                     "select, radians, degrees, atan2, sum, prod and declared functions)");
    in_.fail_expected(t, expected);
  }
  const Value* v = in_.lookup(t);
  if (!v && in_.peek().is("("))
    in_.fail_at(t, "'" + std::string(w) + "' is not a declared function" +
                       (w.starts_with("f_") ? " (the f_… functions are declared in functions.inc)" : ""));
  if (!v) return variable(t);
  if (const auto* n = std::get_if<Numeric>(v); n && n->terms == 1 && !n->colour) return constant(n->v[0], t.loc);
  if (const auto* f = std::get_if<std::shared_ptr<const FunctionValue>>(v)) return parse_call(t, *f);
  in_.fail_expected(t, expected);
}

// x y z u v (the parameter of that name, or 0), a sum()/prod() variable, or a parameter.
int FunctionParser::variable(const Token& name) {
  Node n;
  n.kind = Kind::variable;
  n.loc = name.loc;
  const std::string_view w = name.text;
  auto axis_slot = [this](std::string_view a, std::string_view b) {
    int slot = -1;   // the last parameter of that name, as POV-Ray loads them in order
    for (std::size_t i = 0; i < parameters_.size(); ++i)
      if (parameters_[i] == a || parameters_[i] == b) slot = static_cast<int>(i);
    return slot;
  };
  if (w == "x" || w == "u") n.slot = axis_slot("x", "u");
  else if (w == "y" || w == "v") n.slot = axis_slot("y", "v");
  else if (w == "z") n.slot = axis_slot("z", "z");
  else {
    for (auto it = locals_.rbegin(); it != locals_.rend() && n.slot < 0; ++it)
      if (it->name == w) n.slot = it->slot;
    for (std::size_t i = 0; i < parameters_.size() && n.slot < 0; ++i)
      if (parameters_[i] == w) n.slot = static_cast<int>(i);
    if (n.slot < 0) {
      std::string known;
      for (const auto& p : parameters_) known += (known.empty() ? "" : ", ") + p;
      in_.fail_at(name, "'" + std::string(w) + "' is neither a parameter of this function (" + known +
                            ") nor a declared float");
    }
  }
  return add(std::move(n));
}

int FunctionParser::parse_builtin(const Token& name, const BuiltinInfo& info) {
  Node n;
  n.kind = Kind::builtin;
  n.builtin = info.kind;
  n.math = info.math;
  n.loc = name.loc;
  in_.expect("(", " after '" + std::string(name.text) + "'");
  const bool loop = info.kind == Builtin::sum || info.kind == Builtin::prod;
  if (loop) {
    // sum(i, from, to, expr): the variable is in scope from the second argument on.
    Token var = in_.next();
    const bool axis = var.is("x") || var.is("y") || var.is("z") || var.is("u") || var.is("v");
    if (!axis && (var.kind != TokenKind::identifier || is_reserved_word(var.text) || in_.lookup(var)))
      in_.fail_expected(var, "the name of the " + std::string(name.text) +
                                 "() variable (an undeclared identifier) as its first argument");
    n.local = frame_size_;
    frame_size_ += 3;
    locals_.push_back({std::string(var.text), n.local + 1});
    in_.expect(",", " after the variable of " + std::string(name.text) + "()");
  }
  do {
    n.args.push_back(parse_body_expression());
  } while (in_.accept(","));
  if (loop) locals_.pop_back();
  Token close = in_.next();
  if (!close.is(")")) in_.fail_expected(close, "',' or ')' in the arguments of " + std::string(name.text));
  const int count = static_cast<int>(n.args.size()) + (loop ? 1 : 0);
  auto wrong = [&](const std::string& expected) {
    in_.fail_at(name, "'" + std::string(name.text) + "' takes " + expected + ", found " + std::to_string(count));
  };
  switch (info.kind) {
    case Builtin::math1: case Builtin::radians: case Builtin::degrees: case Builtin::sqr:
      if (count != 1) wrong("one parameter");
      break;
    case Builtin::math2: case Builtin::pow:
      if (count != 2) wrong("two parameters");
      break;
    case Builtin::min: case Builtin::max:
      if (count < 2) wrong("at least two parameters");
      break;
    case Builtin::select:
      if (count != 3 && count != 4) wrong("three or four parameters");
      break;
    case Builtin::sum: case Builtin::prod:
      if (count != 4) wrong("four parameters");
      break;
  }
  return add(std::move(n));
}

int FunctionParser::parse_call(const Token& name, std::shared_ptr<const FunctionValue> fn) {
  Node n;
  n.kind = Kind::call;
  n.loc = name.loc;
  in_.expect("(", " after the function '" + std::string(name.text) + "'");
  do {
    n.args.push_back(parse_body_expression());
  } while (in_.accept(","));
  Token close = in_.next();
  if (!close.is(")")) in_.fail_expected(close, "',' or ')' in the arguments of " + std::string(name.text));
  if (static_cast<int>(n.args.size()) != fn->parameter_count)
    in_.fail_at(name, "the function '" + std::string(name.text) + "' takes " + std::to_string(fn->parameter_count) +
                          " parameter(s), found " + std::to_string(n.args.size()));
  if (fn->return_size > 0) {
    // A vector function's value is used through one of its components.
    Token dot = in_.next();
    if (!dot.is("."))
      in_.fail_expected(dot, "'.' and a component (x, y, z, …) after the vector function '" +
                                 std::string(name.text) + "'");
    n.member = component(in_.next(), *fn, name);
  }
  n.fn = std::move(fn);
  return add(std::move(n));
}

int FunctionParser::component(const Token& member, const FunctionValue& fn, const Token& name) {
  static const std::pair<std::string_view, int> members[] = {
      {"x", 0}, {"u", 0}, {"red", 0}, {"y", 1}, {"v", 1}, {"green", 1}, {"z", 2}, {"blue", 2},
      {"t", 3}, {"filter", 3}, {"transmit", 4}, {"gray", 5}, {"grey", 5}, {"hf", 6}};
  for (const auto& [word, index] : members) {
    if (member.kind != TokenKind::identifier || member.text != word) continue;
    const int needs = index >= 5 ? 3 : index + 1;
    if (needs > fn.return_size)
      in_.fail_at(member, "'." + std::string(word) + "' selects a component that the " +
                              std::to_string(fn.return_size) + "-component result of '" + std::string(name.text) +
                              "' does not have");
    return index;
  }
  in_.fail_expected(member, "a component name (x, y, z, t, u, v, red, green, blue, gray, filter, transmit)");
}

// ---- folding ------------------------------------------------------------------------------------------------

bool FunctionParser::has_variable(int i) const {
  const Node& n = nodes_[static_cast<std::size_t>(i)];
  switch (n.kind) {
    case Kind::constant: return false;
    case Kind::variable: return true;
    case Kind::group: case Kind::neg: return has_variable(n.child);
    case Kind::chain:
      for (const auto& item : n.items)
        if (has_variable(item.node)) return true;
      return false;
    case Kind::builtin: case Kind::call:
      for (int a : n.args)
        if (has_variable(a)) return true;
      return false;
  }
  return false;
}

namespace {
double fold(Op op, double l, double r) {
  switch (op) {
    case Op::eq: return l == r;
    case Op::ne: return l != r;
    case Op::lt: return l < r;
    case Op::le: return l <= r;
    case Op::gt: return l > r;
    case Op::ge: return l >= r;
    case Op::add: return l + r;
    case Op::sub: return l - r;
    case Op::or_: return (static_cast<double>(l != 0) + static_cast<double>(r != 0)) != 0;
    case Op::mul: return l * r;
    case Op::div: return l / r;
    case Op::and_: return static_cast<double>(l != 0) * static_cast<double>(r != 0);
    case Op::pow: return std::pow(l, r);
    case Op::first: break;
  }
  return r;
}
}  // namespace

void FunctionParser::optimise(int i) {
  Node& n = nodes_[static_cast<std::size_t>(i)];
  switch (n.kind) {
    case Kind::constant: case Kind::variable: return;
    case Kind::group: optimise(n.child); return;
    case Kind::neg: {
      const int child = n.child;
      optimise(child);
      const Node& c = nodes_[static_cast<std::size_t>(child)];
      if (c.kind == Kind::constant) {
        const double v = -c.number;
        Node& self = nodes_[static_cast<std::size_t>(i)];
        self.kind = Kind::constant;
        self.number = v;
      }
      return;
    }
    case Kind::chain: {
      Node chain = std::move(n);
      optimise_chain(chain);
      nodes_[static_cast<std::size_t>(i)] = std::move(chain);
      return;
    }
    case Kind::builtin:
      if (n.builtin == Builtin::pow) {
        // pow(a, b) becomes the chain a ^ b inside a group (never a constant for the chain around it).
        Node chain;
        chain.kind = Kind::chain;
        chain.loc = n.loc;
        chain.items.push_back({Op::first, nodes_[static_cast<std::size_t>(n.args[0])].child, n.loc});
        chain.items.push_back({Op::pow, nodes_[static_cast<std::size_t>(n.args[1])].child, n.loc});
        const int c = add(std::move(chain));
        Node& self = nodes_[static_cast<std::size_t>(i)];
        self.kind = Kind::group;
        self.child = c;
        self.args.clear();
        optimise(c);
        return;
      }
      [[fallthrough]];
    case Kind::call:
      if (!n.args.empty()) optimise(n.args[0]);   // POV-Ray folds only the first argument
      return;
  }
}

void FunctionParser::optimise_chain(Node& chain) {
  auto& items = chain.items;
  optimise(items[0].node);
  bool variable_so_far = has_variable(items[0].node);
  for (std::size_t k = 1; k < items.size(); ++k) {
    Node* right = &nodes_[static_cast<std::size_t>(items[k].node)];
    // `- c` becomes `+ (-c)` (only a literal constant: before the operand is folded).
    if (items[k].op == Op::sub && right->kind == Kind::constant) {
      items[k].op = Op::add;
      right->number = -right->number;
    }
    optimise(items[k].node);
    right = &nodes_[static_cast<std::size_t>(items[k].node)];
    variable_so_far = variable_so_far || has_variable(items[k].node);
    Node& left = nodes_[static_cast<std::size_t>(items[k - 1].node)];
    const bool multiplicative = items[k].op == Op::mul || items[k].op == Op::div;
    if (left.kind == Kind::constant && right->kind == Kind::constant && (!multiplicative || !variable_so_far)) {
      left.number = fold(items[k].op, left.number, right->number);
      items.erase(items.begin() + static_cast<std::ptrdiff_t>(k));
      --k;
    }
  }
  if (items.size() == 1 && nodes_[static_cast<std::size_t>(items[0].node)].kind == Kind::constant) {
    const double v = nodes_[static_cast<std::size_t>(items[0].node)].number;
    chain.kind = Kind::constant;
    chain.number = v;
    items.clear();
  }
}

// ---- code generation ------------------------------------------------------------------------------------------

void FunctionParser::emit(FnOp op, int a, int b, double k, int c) {
  FnInstr in;
  in.op = op;
  in.a = a;
  in.b = static_cast<std::uint8_t>(b);
  in.c = c;
  in.k = k;
  out_->code.push_back(in);
  switch (op) {
    case FnOp::konst: case FnOp::load: ++depth_; break;
    case FnOp::add: case FnOp::sub: case FnOp::mul: case FnOp::div: case FnOp::pow: case FnOp::cmp:
    case FnOp::logic_and: case FnOp::logic_or: case FnOp::min2: case FnOp::max2: case FnOp::math2:
    case FnOp::select: case FnOp::store: case FnOp::accumulate:
      --depth_;
      break;
    case FnOp::loop_test: depth_ -= 2; break;
    case FnOp::call: case FnOp::internal: depth_ += 1 - b; break;
    default: break;
  }
  out_->max_stack = std::max(out_->max_stack, depth_);
}

int FunctionParser::callee_index(const std::shared_ptr<const FunctionValue>& fn) {
  auto& callees = out_->callees;
  for (std::size_t i = 0; i < callees.size(); ++i)
    if (callees[i] == fn) return static_cast<int>(i);
  callees.push_back(fn);
  return static_cast<int>(callees.size() - 1);
}

void FunctionParser::compile(int i) {
  const Node& n = nodes_[static_cast<std::size_t>(i)];
  switch (n.kind) {
    case Kind::constant: emit(FnOp::konst, 0, 0, n.number); return;
    case Kind::variable:
      if (n.slot < 0) emit(FnOp::konst, 0, 0, 0.0);
      else emit(FnOp::load, n.slot);
      return;
    case Kind::group: compile(n.child); return;
    case Kind::neg:
      compile(n.child);
      emit(FnOp::neg);
      return;
    case Kind::chain: compile_chain(i); return;
    case Kind::builtin: compile_builtin(i); return;
    case Kind::call: compile_call(i); return;
  }
}

void FunctionParser::compile_chain(int i) {
  const std::vector<ChainItem> items = nodes_[static_cast<std::size_t>(i)].items;
  compile(items[0].node);
  for (std::size_t k = 1; k < items.size(); ++k) {
    const Op op = items[k].op;
    const Node& operand = nodes_[static_cast<std::size_t>(items[k].node)];
    if (operand.kind == Kind::constant) {
      const double c = operand.number;
      bool done = true;
      switch (op) {
        case Op::add: if (c != 0.0) emit(FnOp::addk, 0, 0, c); break;
        case Op::sub: if (c != 0.0) emit(FnOp::subk, 0, 0, c); break;
        case Op::mul: if (c != 1.0) emit(FnOp::mulk, 0, 0, c); break;
        case Op::div:
          if (c == 0.0) in_.fail(items[k].loc, "division by zero in the function");
          if (c != 1.0) emit(FnOp::mulk, 0, 0, 1.0 / c);
          break;
        case Op::pow:
          if (c == 0.0) {
            in_.warn(items[k].loc, "zero power optimised to the constant 1.0");
            emit(FnOp::pow_seq, 0);   // the base is replaced by 1
            break;
          }
          if (c >= 2 && c <= 8 && c == std::floor(c)) emit(FnOp::pow_seq, static_cast<int>(c));
          else done = false;
          break;
        default: done = false; break;
      }
      if (done) continue;
    }
    compile(items[k].node);
    switch (op) {
      case Op::or_: emit(FnOp::logic_or); break;
      case Op::and_: emit(FnOp::logic_and); break;
      case Op::eq: emit(FnOp::cmp, int(FnCompare::eq)); break;
      case Op::ne: emit(FnOp::cmp, int(FnCompare::ne)); break;
      case Op::lt: emit(FnOp::cmp, int(FnCompare::lt)); break;
      case Op::le: emit(FnOp::cmp, int(FnCompare::le)); break;
      case Op::gt: emit(FnOp::cmp, int(FnCompare::gt)); break;
      case Op::ge: emit(FnOp::cmp, int(FnCompare::ge)); break;
      case Op::add: emit(FnOp::add); break;
      case Op::sub: emit(FnOp::sub); break;
      case Op::mul: emit(FnOp::mul); break;
      case Op::div: emit(FnOp::div); break;
      case Op::pow: emit(FnOp::pow); break;
      case Op::first: break;
    }
  }
}

void FunctionParser::compile_builtin(int i) {
  const Node n = nodes_[static_cast<std::size_t>(i)];
  switch (n.builtin) {
    case Builtin::math1:
      compile(n.args[0]);
      emit(FnOp::math1, n.math);
      return;
    case Builtin::radians:
      compile(n.args[0]);
      emit(FnOp::mulk, 0, 0, M_PI / 180.0);
      return;
    case Builtin::degrees:
      compile(n.args[0]);
      emit(FnOp::mulk, 0, 0, 180.0 / M_PI);
      return;
    case Builtin::sqr:
      compile(n.args[0]);
      emit(FnOp::sqr);
      return;
    case Builtin::math2:
      compile(n.args[0]);
      compile(n.args[1]);
      emit(FnOp::math2, n.math);
      return;
    case Builtin::pow:   // not folded (a later argument of a call): the general power
      compile(n.args[0]);
      compile(n.args[1]);
      emit(FnOp::pow);
      return;
    case Builtin::min: case Builtin::max:
      compile(n.args[0]);
      for (std::size_t k = 1; k < n.args.size(); ++k) {
        compile(n.args[k]);
        emit(n.builtin == Builtin::min ? FnOp::min2 : FnOp::max2);
      }
      return;
    case Builtin::select: {
      // [cond] select → (== 0) [third] jump end; (< 0) [second] jump end; (> 0) [fourth]
      compile(n.args[0]);
      const std::size_t branch = out_->code.size();
      emit(FnOp::select);
      const int depth = depth_;
      compile(n.args[2]);
      const std::size_t jump1 = out_->code.size();
      emit(FnOp::jump);
      depth_ = depth;
      out_->code[branch].a = here();
      out_->code[branch].c = static_cast<int>(branch + 1);
      compile(n.args[1]);
      std::size_t jump2 = 0;
      if (n.args.size() == 4) {
        jump2 = out_->code.size();
        emit(FnOp::jump);
        depth_ = depth;
        out_->code[branch].c = here();
        compile(n.args[3]);
      }
      out_->code[jump1].a = here();
      if (jump2) out_->code[jump2].a = here();
      return;
    }
    case Builtin::sum: case Builtin::prod: {
      const int total = n.local, var = n.local + 1, end = n.local + 2;
      compile(n.args[0]);
      emit(FnOp::store, var);
      compile(n.args[1]);
      emit(FnOp::store, end);
      emit(FnOp::konst, 0, 0, n.builtin == Builtin::sum ? 0.0 : 1.0);
      emit(FnOp::store, total);
      const int loop = here();
      emit(FnOp::load, var);
      emit(FnOp::load, end);
      const std::size_t test = out_->code.size();
      emit(FnOp::loop_test);
      compile(n.args[2]);
      emit(FnOp::accumulate, total, n.builtin == Builtin::sum ? 0 : 1);
      emit(FnOp::load, var);
      emit(FnOp::addk, 0, 0, 1.0);
      emit(FnOp::store, var);
      emit(FnOp::jump, loop);
      out_->code[test].a = here();
      emit(FnOp::load, total);
      return;
    }
  }
}

void FunctionParser::compile_call(int i) {
  const Node n = nodes_[static_cast<std::size_t>(i)];
  for (int a : n.args) compile(a);
  const int argc = static_cast<int>(n.args.size());
  const FunctionValue& f = *n.fn;
  switch (f.kind) {
    case FunctionValue::Kind::expression: emit(FnOp::call, callee_index(n.fn), argc); return;
    case FunctionValue::Kind::internal:
      if (internal_function_info(f.internal_id).evaluable) {
        emit(FnOp::internal, f.internal_id, argc);
        return;
      }
      break;
    case FunctionValue::Kind::transform:
    case FunctionValue::Kind::spline:
      emit(FnOp::vector_call, callee_index(n.fn), n.member);
      depth_ += 1 - argc;
      return;
    case FunctionValue::Kind::pigment:
      if (f.colour || f.prepared_pigment) {
        emit(FnOp::vector_call, callee_index(n.fn), n.member);
        depth_ += 1 - argc;
        return;
      }
      break;
    case FunctionValue::Kind::pattern:   // a float function of x, y, z: its value is component 0
      if (f.pattern) {
        emit(FnOp::vector_call, callee_index(n.fn), 0);
        depth_ += 1 - argc;
        return;
      }
      break;
  }
  // Evaluating it is refused (noise, patterns); defining a function that calls it is not.
  emit(FnOp::unsupported, callee_index(n.fn));
  depth_ += 1 - argc;
}

// ---- the FunctionValues part: the interpreter's hooks ---------------------------------------------------------

std::optional<Value> FunctionValues::try_parse_rvalue(const Token& first) {
  if (first.is("function")) return Value(FunctionParser(*this).parse_definition(first));
  const Value* v = lookup(first);
  const auto* found = v ? std::get_if<std::shared_ptr<const FunctionValue>>(v) : nullptr;
  if (!found) return std::nullopt;
  // Held before looking further: the look may end the macro whose local `first` is (`#local F = function {…} F`
  // as a macro's result, or `A()(2)`), after which the name no longer resolves.
  std::shared_ptr<const FunctionValue> held = *found;
  const Token after = peek_raw();   // raw: a directive after `#declare G = F` runs once G is stored
  if (after.is("(")) {   // a call: the value is an expression (F(1,2,3) + 1), its first operand this call
    return Value(parse_additive_after(call(first, std::move(held))).stored());
  }
  // `F + 1` or `F.x` is a call without its arguments (POV-Ray: "incomplete function call").
  if (after.is("+") || after.is("-") || after.is("*") || after.is("/") || after.is("."))
    fail_expected(after, "'(' and the arguments of the function '" + std::string(first.text) +
                             "' (an incomplete function call)");
  return Value(std::move(held));   // `#declare G = F;`: G is a copy (an immutable value, so shared)
}

std::shared_ptr<const FunctionValue> FunctionValues::parse_definition(const Token& keyword) {
  return FunctionParser(*this).parse_definition(keyword);
}

Numeric FunctionValues::call(const Token& name, std::shared_ptr<const FunctionValue> fn) {
  // `fn` is held here: parsing the arguments may end the macro or include file whose local it is.
  const FunctionValue& f = *fn;
  const std::string what = "the function '" + std::string(name.text) + "'";
  Token open = next();
  if (!open.is("(")) fail_expected(open, "'(' after " + what + " (a function is used by calling it)");
  double args[kMaxParameters] = {};
  for (int i = 0; i < f.parameter_count; ++i) {
    if (i > 0) accept(",");   // commas between the arguments are optional, as in POV-Ray
    if (Token at = peek(); at.is(")"))
      fail_at(at, what + " takes " + std::to_string(f.parameter_count) + " argument(s), found " + std::to_string(i));
    args[i] = parse_float();
  }
  Token close = next();
  if (close.is(","))
    fail_at(close, what + " takes only " + std::to_string(f.parameter_count) + " argument(s)");
  if (!close.is(")")) fail_expected(close, "')' closing the call of " + what);
  double out[5] = {0, 0, 0, 0, 0};
  double result = 0;
  try {
    result = evaluate_function(f, args, out, noise_generator(), budget());
  } catch (const FunctionError& e) {
    fail_at(name, e.what());
  }
  if (f.return_size == 0) return Numeric::scalar(result);
  Numeric n;
  n.terms = f.return_size;
  for (int i = 0; i < 5; ++i) n.v[static_cast<std::size_t>(i)] = out[i];
  n.colour = f.kind == FunctionValue::Kind::pigment;
  return n;
}

// POV-Ray refuses to declare a name again while it holds a function, and to turn a declared value of another
// type into a function (§3: #undef first).
void FunctionValues::check_redeclaration(const Token& name, bool local, const Value& value) {
  // By the token's NameId: this runs for every #declare, most of them of plain values.
  const Value* visible = name.name ? symbols_.find(name.name) : symbols_.find(name.text);
  if (visible && std::holds_alternative<std::shared_ptr<const FunctionValue>>(*visible))
    fail_at(name, "redeclaring the function '" + std::string(name.text) + "' is not allowed: #undef it first");
  if (!std::holds_alternative<std::shared_ptr<const FunctionValue>>(value) || !visible) return;
  const std::string n(name.text);
  if (local && symbols_.level_of(n) != symbols_.depth() - 1) return;   // a new local in this scope
  fail_at(name, "cannot redefine the " + value_type_name(*visible) + " identifier '" + n +
                    "' as a function: #undef it first");
}

}  // namespace povtrace::sdl

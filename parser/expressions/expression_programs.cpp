// Expression programs (expression_programs.hpp): the replayed expressions of loops and macro bodies, compiled from
// their kept tokens and run instead of the recursive descent of expressions.cpp.
#include "parser/expressions/expression_programs.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <optional>

#include "parser/directives/directive_runner.hpp"
#include "parser/expressions/builtins.hpp"
#include "parser/expressions/numeric_ops.hpp"
#include "parser/lexing/nesting_limit.hpp"

// ---- expression programs ---------------------------------------------------------------------------------
// Why a second engine next to the recursive descent above (issue 17 asked for one engine or the reason for two):
// - The recursive descent is the only definition of SDL expressions, and it must stay: the grammar depends on
//   values (a string identifier makes a string comparison, a function or spline identifier takes a call, an array
//   takes subscripts), directives and macro calls may stand between any two tokens, and warnings, rand() and
//   trace() must happen in the order of the tokens. No compile-then-run engine can read SDL in general.
// - Expression programs are a memo of that parse for the pure, context-free subset of expressions read again from
//   kept tokens in #while/#for loops and macro bodies. They are compiled from tokens alone, computed with the same
//   helpers (promote, componentwise, compare, quiet_float_call), and decline — consuming nothing, leaving the
//   expression to the full parse — wherever the parse would warn, fail or branch on a value's type.
// - Without them replayed loops parse several times slower: at f1be3ab with programs off (ParseOptions::
//   expression_programs = false), bench's parse_while took 1.46 s against 0.45 s and parse_macro 0.158 s against
//   0.115 s (medians of 7 interleaved runs). The function VM (runtime/function_vm.cpp) is no third engine for SDL:
//   it is POV-Ray's function compiler, whose folding and comparisons differ from SDL's on purpose.
// - They are checked against the full parse by tests/parser/expression_replay_test.cpp, and every reference scene
//   is rendered with them off too (--no-specialise turns them off; tests/regression/same_image.cmake).
namespace povtrace::sdl {

namespace {
// A program is refused beyond this: its stack lives in a fixed array.
constexpr int kProgramStack = 8;
}  // namespace

ExpressionPrograms::ExpressionPrograms(const ParseOptions& options, TokenStream& stream, const SymbolTable& symbols,
                                       const DirectiveRunner& directives)
    : enabled_(options.expression_programs && !options.max_tokens),
      stream_(stream),
      symbols_(symbols),
      directives_(directives) {}

// Reads the grammar of parse_expression … parse_primary once more over the kept tokens, emitting the operations
// in the order the parse would compute them. It looks at tokens only, never at values.
class ExpressionPrograms::ProgramCompiler {
 public:
  enum class Result { done, never, not_yet };
  ProgramCompiler(std::vector<ExpressionOp>& ops, const SymbolTable& symbols, const FileTokens& tokens,
                  std::size_t at)
      : ops_(ops), symbols_(symbols), tokens_(tokens), text_(tokens.file().text), j_(at) {}

  Result compile(bool full, ExpressionProgram& p) {
    p.first_op = static_cast<std::uint32_t>(ops_.size());
    const bool ok = (full ? full_level() : additive()) && at(j_);   // the token after it is plain, too
    if (!ok) {
      ops_.resize(p.first_op);
      return result_;
    }
    p.op_count = static_cast<std::uint32_t>(ops_.size()) - p.first_op;
    p.end = static_cast<std::uint32_t>(j_);
    p.usable = true;
    return Result::done;
  }

 private:
  // Kept token j where the program may read it; nullptr (and why) where it stops: not lexed yet (a loop's first
  // round), or a '#' or the end of a file, where the parse would run a directive or change frames.
  const LexedToken* at(std::size_t j) {
    if (j >= tokens_.size()) return stop(Result::not_yet);
    const LexedToken& k = tokens_[j];
    if (k.kind() == TokenKind::end_of_input || is(&k, "#")) return stop(Result::never);
    return &k;
  }
  const LexedToken* stop(Result r) {
    result_ = r;
    return nullptr;
  }
  bool never() {
    result_ = Result::never;
    return false;
  }
  std::string_view text(const LexedToken& k) const { return std::string_view(text_.data() + k.offset, k.length()); }
  bool is(const LexedToken* k, std::string_view symbol) const {
    return k && k->kind() == TokenKind::symbol && text(*k) == symbol;
  }
  bool emit(ExpressionOp op, int pops, int pushes) {
    stack_ += pushes - pops;
    if (stack_ > kProgramStack) return never();
    ops_.push_back(op);
    return true;
  }
  bool emit(ExpressionOp::Code code, int pops = 2) { return emit(ExpressionOp{code, 0, 0, 0, nullptr}, pops, 1); }

  bool full_level() {   // parse_expression
    if (!comparison()) return false;
    while (true) {
      const LexedToken* k = at(j_);
      if (!k) return false;
      const bool a = is(k, "&");
      if (!a && !is(k, "|")) break;
      ++j_;
      if (!comparison() || !emit(a ? ExpressionOp::Code::and_ : ExpressionOp::Code::or_)) return false;
    }
    return is(at(j_), "?") ? never() : result_ == Result::done;
  }
  bool comparison() {
    const LexedToken* k = at(j_);
    if (!k) return false;
    // A string operand makes a string comparison (an identifier holding a string is caught when the program runs).
    if (k->kind() == TokenKind::string || (k->kind() == TokenKind::identifier && is_string_function(text(*k))))
      return never();
    if (!additive()) return false;
    while (true) {
      k = at(j_);
      if (!k) return false;
      const Comparison c = comparison_of(k->kind(), text(*k));
      if (c == Comparison::none) return true;
      ++j_;
      if (!additive()) return false;
      if (!emit(ExpressionOp{ExpressionOp::Code::compare, static_cast<std::uint8_t>(c), 0, 0, nullptr}, 2, 1))
        return false;
    }
  }
  bool additive() {   // parse_additive
    if (!multiplicative()) return false;
    while (true) {
      const LexedToken* k = at(j_);
      if (!k) return false;
      const bool plus = is(k, "+");
      if (!plus && !is(k, "-")) return true;
      ++j_;
      if (!multiplicative() || !emit(plus ? ExpressionOp::Code::add : ExpressionOp::Code::sub)) return false;
    }
  }
  bool multiplicative() {   // parse_multiplicative
    if (!unary()) return false;
    while (true) {
      const LexedToken* k = at(j_);
      if (!k) return false;
      const bool times = is(k, "*");
      if (!times && !is(k, "/")) return true;
      ++j_;
      if (!unary() || !emit(times ? ExpressionOp::Code::mul : ExpressionOp::Code::div)) return false;
    }
  }
  bool unary() {   // parse_unary and parse_primary
    if (++depth_ > kNestingDepth) return never();
    const bool ok = operand();
    --depth_;
    return ok;
  }
  bool operand() {
    const LexedToken* k = at(j_);
    if (!k) return false;
    switch (k->kind()) {
      case TokenKind::number:
        ++j_;
        return emit(ExpressionOp{ExpressionOp::Code::number, 0, 0, tokens_.number(*k), nullptr}, 0, 1) &&
               no_postfix();
      case TokenKind::identifier: {
        ++j_;
        if (!symbols_.is_reserved(k->payload))
          return emit(ExpressionOp{ExpressionOp::Code::name, 0, k->payload, 0, nullptr}, 0, 1) && no_postfix();
        const std::string_view w = text(*k);
        // The constants of parse_primary whose value never changes.
        if (w == "pi" || w == "true" || w == "yes" || w == "on" || w == "false" || w == "no" || w == "off") {
          const double v = w == "pi" ? M_PI : (w == "true" || w == "yes" || w == "on") ? 1.0 : 0.0;
          return emit(ExpressionOp{ExpressionOp::Code::number, 0, 0, v, nullptr}, 0, 1) && no_postfix();
        }
        if (const FloatFunction* f = find_float_function(w)) return call(*f) && no_postfix();
        return never();
      }
      case TokenKind::symbol: break;
      default: return never();
    }
    const std::string_view s = text(*k);
    ++j_;
    if (s == "-") return unary() && emit(ExpressionOp::Code::neg, 1);
    if (s == "+") return unary();
    if (s == "!") return unary() && emit(ExpressionOp::Code::not_, 1);
    if (s == "(") {
      if (!full_level()) return false;
      const LexedToken* close = at(j_);
      if (!close) return false;
      if (!is(close, ")")) return never();
      ++j_;
      return no_postfix();
    }
    if (s == "<") return vector() && no_postfix();
    return never();
  }
  bool no_postfix() {   // a component selector (.x) is left to the parse
    const LexedToken* k = at(j_);
    if (!k) return false;
    return is(k, ".") ? never() : true;
  }
  bool vector() {   // parse_vector_literal, after its '<'
    int count = 0;
    while (true) {
      if (count == 5) return never();
      if (!additive()) return false;
      ++count;
      const LexedToken* k = at(j_);
      if (!k) return false;
      if (is(k, ">")) { ++j_; break; }
      if (is(k, ",")) {
        ++j_;
        const LexedToken* after = at(j_);
        if (!after) return false;
        if (is(after, ">")) { ++j_; break; }
      }
      // any other token: commas between components are optional
    }
    if (count < 2) return never();
    return emit(ExpressionOp{ExpressionOp::Code::vector, static_cast<std::uint8_t>(count), 0, 0, nullptr}, count, 1);
  }
  bool call(const FloatFunction& f) {   // parse_call_arguments
    const LexedToken* k = at(j_);
    if (!k) return false;
    if (!is(k, "(")) return never();
    ++j_;
    std::size_t count = 0;
    if (f.max_args == 1) {
      if (!full_level()) return false;
      count = 1;
    } else {
      for (std::size_t i = 0; i < f.min_args; ++i) {
        if (i > 0) {
          const LexedToken* comma = at(j_);
          if (!comma) return false;
          if (is(comma, ",")) ++j_;
        }
        if (!additive()) return false;
        ++count;
      }
      while (count < f.max_args) {
        const LexedToken* comma = at(j_);
        if (!comma) return false;
        if (!is(comma, ",")) break;
        ++j_;
        if (!additive()) return false;
        ++count;
      }
    }
    const LexedToken* close = at(j_);
    if (!close) return false;
    if (!is(close, ")") || count < f.min_args) return never();
    ++j_;
    const auto n = static_cast<int>(count);
    return emit(ExpressionOp{ExpressionOp::Code::call, static_cast<std::uint8_t>(count), 0, 0, &f}, n, 1);
  }

  std::vector<ExpressionOp>& ops_;
  const SymbolTable& symbols_;
  const FileTokens& tokens_;
  const std::string& text_;
  std::size_t j_;
  Result result_ = Result::done;
  int stack_ = 0;
  int depth_ = 0;
};

namespace {
// What the program's run found: its value, an operand or operation it does not cover (the parse then reads
// the expression), or values beyond floats (run again over full Numerics).
enum class Run { value, decline, wider };
}  // namespace

bool ExpressionPrograms::run(bool full, Numeric& out, int nesting) {
  // With a token limit every token is counted by next(); a deprecated name warns where it is read.
  if (!enabled_ || stream_.has_pushed_back() || symbols_.any_deprecated()) return false;
  const TokenStream::Frame& f = stream_.frame();
  const unsigned level = full ? 1 : 0;
  std::uint32_t note = f.tokens->note(f.index, level);
  if (note == 0) {
    if (!directives_.replaying()) return false;   // read once: not worth a program
    ExpressionProgram made;
    ProgramCompiler compiler(program_ops_, symbols_, *f.tokens, f.index);
    if (compiler.compile(full, made) == ProgramCompiler::Result::not_yet) return false;
    if (made.usable) {
      programs_.push_back(made);
      note = static_cast<std::uint32_t>(programs_.size() + 1);
    } else {
      note = 1;
    }
    f.tokens->set_note(f.index, level, note);
  }
  if (note == 1 || nesting + kNestingDepth > kMaxNesting ||
      !stack_room_below(static_cast<const char*>(__builtin_frame_address(0))))
    return false;
  const ExpressionProgram& p = programs_[note - 2];
  const ExpressionOp* ops = program_ops_.data() + p.first_op;
  const ExpressionOp* const end = ops + p.op_count;

  // Floats only, on a stack of doubles: what loops compute. The operations are those of the parse on one-term
  // Numerics (componentwise() of two floats is the float operation).
  auto floats = [&]() {
    double st[kProgramStack];
    int sp = 0;
    for (const ExpressionOp* op = ops; op != end; ++op) {
      switch (op->code) {
        case ExpressionOp::Code::number: st[sp++] = op->number; break;
        case ExpressionOp::Code::name: {
          const Value* v = symbols_.find(op->name);
          const Numeric* n = v ? std::get_if<Numeric>(v) : nullptr;
          if (!n) return Run::decline;
          if (n->terms != 1 || n->colour) return Run::wider;
          st[sp++] = n->v[0];
          break;
        }
        case ExpressionOp::Code::neg: st[sp - 1] = -st[sp - 1]; break;
        case ExpressionOp::Code::not_: st[sp - 1] = std::fabs(st[sp - 1]) <= kEqualEpsilon ? 1.0 : 0.0; break;
        case ExpressionOp::Code::add: --sp; st[sp - 1] += st[sp]; break;
        case ExpressionOp::Code::sub: --sp; st[sp - 1] -= st[sp]; break;
        case ExpressionOp::Code::mul: --sp; st[sp - 1] *= st[sp]; break;
        case ExpressionOp::Code::div:
          --sp;
          if (st[sp] == 0.0) return Run::decline;   // the parse warns
          st[sp - 1] /= st[sp];
          break;
        case ExpressionOp::Code::compare:
          --sp;
          st[sp - 1] = compare(static_cast<Comparison>(op->arg), st[sp - 1], st[sp]) ? 1.0 : 0.0;
          break;
        case ExpressionOp::Code::and_:
        case ExpressionOp::Code::or_: {
          --sp;
          const bool a = std::fabs(st[sp - 1]) > kEqualEpsilon, b = std::fabs(st[sp]) > kEqualEpsilon;
          st[sp - 1] = (op->code == ExpressionOp::Code::and_ ? (a && b) : (a || b)) ? 1.0 : 0.0;
          break;
        }
        case ExpressionOp::Code::vector: {
          if (op + 1 != end) return Run::wider;   // a vector operand: the Numeric run
          Numeric n;
          n.terms = op->arg;
          sp -= op->arg;
          for (int i = 0; i < op->arg; ++i) n.v[static_cast<std::size_t>(i)] = st[sp + i];
          out = n;
          return Run::value;
        }
        case ExpressionOp::Code::call: {
          CallArguments args;
          sp -= op->arg;
          for (int i = 0; i < op->arg; ++i) args.push_back(st[sp + i]);
          const std::optional<double> r = quiet_float_call(*op->function, args);
          if (!r) return Run::decline;
          st[sp++] = *r;
          break;
        }
      }
    }
    // Field by field, not through a temporary: copying a just-built Numeric stalled on store forwarding.
    out.v[0] = st[0];
    out.v[1] = out.v[2] = out.v[3] = out.v[4] = 0;
    out.terms = 1;
    out.colour = false;
    return Run::value;
  };

  // Any Numeric, with the parse's promotion and its checks (a float where one is required).
  auto numerics = [&]() {
    std::array<Numeric, kProgramStack> st;
    int sp = 0;
    auto pop_float = [&](double& x) {
      const Numeric& n = st[static_cast<std::size_t>(--sp)];
      x = n.v[0];
      return n.terms == 1;
    };
    for (const ExpressionOp* op = ops; op != end; ++op) {
      Numeric* top = sp > 0 ? &st[static_cast<std::size_t>(sp - 1)] : nullptr;
      switch (op->code) {
        case ExpressionOp::Code::number: st[static_cast<std::size_t>(sp++)] = Numeric::scalar(op->number); break;
        case ExpressionOp::Code::name: {
          const Value* v = symbols_.find(op->name);
          const Numeric* n = v ? std::get_if<Numeric>(v) : nullptr;
          if (!n) return Run::decline;
          st[static_cast<std::size_t>(sp++)] = *n;
          break;
        }
        case ExpressionOp::Code::neg:
          for (int i = 0; i < top->terms; ++i) top->v[static_cast<std::size_t>(i)] = -top->v[static_cast<std::size_t>(i)];
          break;
        case ExpressionOp::Code::not_:
          for (int i = 0; i < top->terms; ++i) {
            double& c = top->v[static_cast<std::size_t>(i)];
            c = std::fabs(c) <= kEqualEpsilon ? 1.0 : 0.0;
          }
          break;
        case ExpressionOp::Code::add:
        case ExpressionOp::Code::sub:
        case ExpressionOp::Code::mul:
        case ExpressionOp::Code::div: {
          --sp;
          Numeric& a = st[static_cast<std::size_t>(sp - 1)];
          const Numeric& b = st[static_cast<std::size_t>(sp)];
          if (op->code == ExpressionOp::Code::add) a = componentwise(a, b, std::plus<>());
          else if (op->code == ExpressionOp::Code::sub) a = componentwise(a, b, std::minus<>());
          else if (op->code == ExpressionOp::Code::mul) a = componentwise(a, b, std::multiplies<>());
          else {
            Numeric divisor = b;
            promote(a, divisor);
            for (int i = 0; i < a.terms; ++i)
              if (divisor.v[static_cast<std::size_t>(i)] == 0.0) return Run::decline;   // the parse warns
            for (int i = 0; i < a.terms; ++i) a.v[static_cast<std::size_t>(i)] /= divisor.v[static_cast<std::size_t>(i)];
          }
          break;
        }
        case ExpressionOp::Code::compare:
        case ExpressionOp::Code::and_:
        case ExpressionOp::Code::or_: {
          double a = 0, b = 0;
          if (!pop_float(b) || !pop_float(a)) return Run::decline;   // the parse's "expected a float"
          bool r = false;
          if (op->code == ExpressionOp::Code::compare) r = compare(static_cast<Comparison>(op->arg), a, b);
          else {
            const bool x = std::fabs(a) > kEqualEpsilon, y = std::fabs(b) > kEqualEpsilon;
            r = op->code == ExpressionOp::Code::and_ ? (x && y) : (x || y);
          }
          st[static_cast<std::size_t>(sp++)] = Numeric::scalar(r ? 1.0 : 0.0);
          break;
        }
        case ExpressionOp::Code::vector:
        case ExpressionOp::Code::call: {
          double c[kProgramStack];
          for (int i = op->arg - 1; i >= 0; --i)
            if (!pop_float(c[i])) return Run::decline;   // parse_float's "expected a float"
          if (op->code == ExpressionOp::Code::vector) {
            Numeric n;
            n.terms = op->arg;
            for (int i = 0; i < op->arg; ++i) n.v[static_cast<std::size_t>(i)] = c[i];
            st[static_cast<std::size_t>(sp++)] = n;
          } else {
            CallArguments args;
            for (int i = 0; i < op->arg; ++i) args.push_back(c[i]);
            const std::optional<double> r = quiet_float_call(*op->function, args);
            if (!r) return Run::decline;
            st[static_cast<std::size_t>(sp++)] = Numeric::scalar(*r);
          }
          break;
        }
      }
    }
    out = st[0];
    return Run::value;
  };

  Run r = floats();
  if (r == Run::wider) r = numerics();
  if (r != Run::value) return false;
  stream_.jump_to(p.end);
  return true;
}
}  // namespace povtrace::sdl

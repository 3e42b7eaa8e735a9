// The stack machine that runs compiled function bodies (function_value.hpp). One value stack holds every active
// call's frame (its parameters, then its sum()/prod() variables) followed by its operands; calls push a frame
// record instead of recursing, so a chain of thousands of functions calling each other needs no C++ stack.
#include <algorithm>
#include <climits>
#include <cmath>
#include <vector>

#include "runtime/function_value.hpp"

namespace povtrace::sdl {

namespace {

// Calls nested deeper than this are refused. Functions cannot call themselves (a function is only visible once
// declared, and cannot be redeclared), so only a very long chain of distinct functions gets here.
constexpr std::size_t kMaxCallDepth = 100000;

// POV-Ray's int(): a C conversion to a 32-bit int; out-of-range values and NaN give INT_MIN as on x86.
double to_int(double v) {
  if (!(v > -2147483649.0 && v < 2147483648.0)) return static_cast<double>(INT_MIN);
  return static_cast<double>(static_cast<int>(v));
}

double math1(FnMath1 f, double v) {
  switch (f) {
    case FnMath1::sin: return std::sin(v);
    case FnMath1::cos: return std::cos(v);
    case FnMath1::tan: return std::tan(v);
    case FnMath1::asin: return std::asin(v);
    case FnMath1::acos: return std::acos(v);
    case FnMath1::atan: return std::atan(v);
    case FnMath1::sinh: return std::sinh(v);
    case FnMath1::cosh: return std::cosh(v);
    case FnMath1::tanh: return std::tanh(v);
    case FnMath1::asinh: return std::asinh(v);
    case FnMath1::acosh: return std::acosh(v);
    case FnMath1::atanh: return std::atanh(v);
    case FnMath1::floor: return std::floor(v);
    case FnMath1::ceil: return std::ceil(v);
    case FnMath1::sqrt: return std::sqrt(v);
    case FnMath1::exp: return std::exp(v);
    case FnMath1::ln: return std::log(v);
    case FnMath1::log: return std::log10(v);
    case FnMath1::int_: return to_int(v);
    case FnMath1::abs: return std::fabs(v);
  }
  return 0;
}

double math2(FnMath2 f, double a, double b) {
  switch (f) {
    case FnMath2::atan2: return std::atan2(a, b);
    case FnMath2::mod: return std::fmod(a, b);
    case FnMath2::div: return to_int(a / b);
  }
  return 0;
}

// POV-Ray's comparisons set a condition code from "right > left" and "right == left" and test it, which decides
// what NaN operands give (`>` and `>=` are true when either side is NaN, `!=` too).
double compare(FnCompare c, double left, double right) {
  const bool greater = right > left, equal = right == left;
  switch (c) {
    case FnCompare::eq: return equal && !greater ? 1 : 0;
    case FnCompare::ne: return !(equal && !greater) ? 1 : 0;
    case FnCompare::lt: return greater ? 1 : 0;
    case FnCompare::le: return greater || equal ? 1 : 0;
    case FnCompare::gt: return !greater && !equal ? 1 : 0;
    case FnCompare::ge: return !greater ? 1 : 0;
  }
  return 0;
}

// x^n for n = 2…8, multiplied in the order POV-Ray's compiler emits (not std::pow: the last bit can differ).
double power_sequence(double b, int n) {
  switch (n) {
    case 0: return 1.0;   // pow(x, 0): POV-Ray loads the constant 1 whatever x is
    case 2: return b * b;
    case 3: return (b * b) * b;
    case 4: { const double s = b * b; return s * s; }
    case 5: { const double s = b * b; const double f = s * s; return f * b; }
    case 6: { const double s = b * b; const double f = s * s; return f * s; }
    case 7: { const double s = b * b; const double f = s * s; return (f * b) * s; }
    case 8: { const double s = b * b; const double f = s * s; return f * f; }
  }
  return std::pow(b, n);
}

// Component `which` of a vector result: 0…4 directly, 5 the gray value, 6 the height-field value (POV-Ray's
// `.gray` and `.hf` members).
double vector_component(const double* v, int which) {
  if (which == 5) return v[0] * 0.297 + v[1] * 0.589 + v[2] * 0.114;
  if (which == 6) return (v[0] + v[1] * (1.0 / 255.0)) * 0.996093;
  return v[which];
}

std::string unsupported_message(const FunctionValue& f) {
  return "unsupported: " + f.description() + " is a POV-Ray feature that povtrace does not render yet";
}

// Values the vector kinds produce; float kinds return through `out[0]`.
void evaluate_native(const FunctionValue& f, const double* args, int noise_generator, double* out) {
  switch (f.kind) {
    case FunctionValue::Kind::internal: {
      const InternalFunctionInfo& info = internal_function_info(f.internal_id);
      if (!info.evaluable) throw FunctionError(unsupported_message(f));
      double p[16];
      std::copy(args, args + info.parameter_count, p);
      out[0] = evaluate_internal_function(f.internal_id, p, noise_generator);
      return;
    }
    case FunctionValue::Kind::transform: {
      const Vec3 r = f.transform.point({args[0], args[1], args[2]});
      out[0] = r.x;
      out[1] = r.y;
      out[2] = r.z;
      return;
    }
    case FunctionValue::Kind::spline: {
      // Only the spline's own components: POV-Ray's f_spline leaves the others as they were (zero).
      const std::array<double, 5> v = evaluate_spline(*f.spline, f.spline->type, args[0]);
      std::copy(v.begin(), v.begin() + f.spline->terms, out);
      return;
    }
    case FunctionValue::Kind::pigment:
      if (f.colour) {
        out[0] = f.colour->r;
        out[1] = f.colour->g;
        out[2] = f.colour->b;
        out[3] = f.colour->f;
        out[4] = f.colour->t;
        return;
      }
      if (f.prepared_pigment) {
        const Colour c = f.prepared_pigment->colour({args[0], args[1], args[2]}, noise_generator);
        out[0] = c.r;
        out[1] = c.g;
        out[2] = c.b;
        out[3] = c.f;
        out[4] = c.t;
        return;
      }
      throw FunctionError(unsupported_message(f));
    case FunctionValue::Kind::pattern:
      if (!f.pattern) throw FunctionError(unsupported_message(f));
      out[0] = f.pattern->value({args[0], args[1], args[2]}, noise_generator);
      return;
    case FunctionValue::Kind::expression: break;
  }
  throw FunctionError(unsupported_message(f));
}

// A growable array whose first N elements live in the object itself: the machine lives on the caller's stack, and
// nearly every evaluation fits there without touching the heap.
template <class T, std::size_t N>
class InlineBuffer {
 public:
  InlineBuffer() = default;
  InlineBuffer(const InlineBuffer&) = delete;
  InlineBuffer& operator=(const InlineBuffer&) = delete;
  T* data() { return data_; }
  // Room for n elements; the first `used` keep their values.
  void reserve(std::size_t n, std::size_t used) {
    if (n <= capacity_) return;
    std::vector<T> grown(std::max(n, capacity_ * 2));
    std::copy(data_, data_ + used, grown.begin());
    heap_ = std::move(grown);
    data_ = heap_.data();
    capacity_ = heap_.size();
  }

 private:
  T inline_[N];
  std::vector<T> heap_;
  T* data_ = inline_;
  std::size_t capacity_ = N;
};

// One evaluation's scratch (value stack and call frames), made on the stack of evaluate_function's caller: no state
// outlives a call, so any number of threads evaluate at once.
class Machine {
 public:
  double run(const FunctionValue& entry, const double* args, int noise_generator, std::uint64_t* steps_left) {
    auto step = [steps_left]() {
      if (!steps_left) return;
      if (*steps_left == 0)
        throw FunctionError("function evaluation stopped: the parse's work limit (ParseOptions::max_tokens) is "
                            "reached in sum(), prod() or function calls");
      --*steps_left;
    };
    std::size_t base = 0;
    std::size_t sp = 0;      // next free stack slot
    std::size_t depth = 0;   // active calls below the current function (frames_ in use)
    const FunctionValue* fn = &entry;
    stack_.reserve(static_cast<std::size_t>(fn->frame_size + fn->max_stack), 0);
    double* s = stack_.data();
    std::copy(args, args + fn->parameter_count, s);
    std::fill(s + fn->parameter_count, s + fn->frame_size, 0.0);
    sp = static_cast<std::size_t>(fn->frame_size);
    const FnInstr* code = fn->code.data();
    std::size_t pc = 0;
    while (true) {
      const FnInstr& in = code[pc++];
      switch (in.op) {
        case FnOp::konst: s[sp++] = in.k; break;
        case FnOp::load: s[sp++] = s[base + static_cast<std::size_t>(in.a)]; break;
        case FnOp::add: --sp; s[sp - 1] = s[sp - 1] + s[sp]; break;
        case FnOp::sub: --sp; s[sp - 1] = s[sp - 1] - s[sp]; break;
        case FnOp::mul: --sp; s[sp - 1] = s[sp - 1] * s[sp]; break;
        case FnOp::div: --sp; s[sp - 1] = s[sp - 1] / s[sp]; break;
        case FnOp::addk: s[sp - 1] += in.k; break;
        case FnOp::subk: s[sp - 1] -= in.k; break;
        case FnOp::mulk: s[sp - 1] *= in.k; break;
        case FnOp::neg: s[sp - 1] = -s[sp - 1]; break;
        case FnOp::sqr: s[sp - 1] = s[sp - 1] * s[sp - 1]; break;
        case FnOp::pow: --sp; s[sp - 1] = std::pow(s[sp - 1], s[sp]); break;
        case FnOp::pow_seq: s[sp - 1] = power_sequence(s[sp - 1], in.a); break;
        case FnOp::cmp: --sp; s[sp - 1] = compare(static_cast<FnCompare>(in.a), s[sp - 1], s[sp]); break;
        case FnOp::logic_and:
          --sp;
          s[sp - 1] = static_cast<double>(s[sp - 1] != 0.0) * static_cast<double>(s[sp] != 0.0);
          break;
        case FnOp::logic_or:
          --sp;
          s[sp - 1] = (static_cast<double>(s[sp - 1] != 0.0) + static_cast<double>(s[sp] != 0.0)) != 0.0 ? 1 : 0;
          break;
        case FnOp::min2: {   // keeps the new value unless it is greater than or equal to the minimum so far
          --sp;
          const double next = s[sp], best = s[sp - 1];
          s[sp - 1] = !(next > best) && !(next == best) ? next : best;
          break;
        }
        case FnOp::max2: {
          --sp;
          const double next = s[sp], best = s[sp - 1];
          s[sp - 1] = next > best ? next : best;
          break;
        }
        case FnOp::math1: s[sp - 1] = math1(static_cast<FnMath1>(in.a), s[sp - 1]); break;
        case FnOp::math2: --sp; s[sp - 1] = math2(static_cast<FnMath2>(in.a), s[sp - 1], s[sp]); break;
        case FnOp::jump:
          if (static_cast<std::size_t>(in.a) < pc) step();   // the back edge of a sum()/prod() loop
          pc = static_cast<std::size_t>(in.a);
          break;
        case FnOp::select: {
          const double c = s[--sp];
          if (c < 0) pc = static_cast<std::size_t>(in.a);
          else if (!(c == 0)) pc = static_cast<std::size_t>(in.c);
          break;
        }
        case FnOp::loop_test: {
          sp -= 2;
          const double i = s[sp], end = s[sp + 1];
          if (!(end > i) && !(end == i)) pc = static_cast<std::size_t>(in.a);
          break;
        }
        case FnOp::store: s[base + static_cast<std::size_t>(in.a)] = s[--sp]; break;
        case FnOp::accumulate: {
          double& acc = s[base + static_cast<std::size_t>(in.a)];
          const double v = s[--sp];
          acc = in.b == 0 ? acc + v : acc * v;
          break;
        }
        case FnOp::internal: {
          double p[16];
          const std::size_t n = in.b;
          sp -= n;
          std::copy(s + sp, s + sp + n, p);
          s[sp++] = evaluate_internal_function(in.a, p, noise_generator);
          break;
        }
        case FnOp::vector_call: {
          const FunctionValue& callee = *fn->callees[static_cast<std::size_t>(in.a)];
          sp -= static_cast<std::size_t>(callee.parameter_count);
          double out[5] = {0, 0, 0, 0, 0};
          evaluate_native(callee, s + sp, noise_generator, out);
          s[sp++] = vector_component(out, in.b);
          break;
        }
        case FnOp::unsupported: throw FunctionError(unsupported_message(*fn->callees[static_cast<std::size_t>(in.a)]));
        case FnOp::call: {
          const FunctionValue* callee = fn->callees[static_cast<std::size_t>(in.a)].get();
          step();
          if (depth >= kMaxCallDepth)
            throw FunctionError("function calls nested more than " + std::to_string(kMaxCallDepth) + " deep");
          frames_.reserve(depth + 1, depth);
          frames_.data()[depth++] = Frame{fn, pc, base};
          base = sp - in.b;
          fn = callee;
          stack_.reserve(base + static_cast<std::size_t>(fn->frame_size + fn->max_stack), sp);
          s = stack_.data();
          std::fill(s + sp, s + base + static_cast<std::size_t>(fn->frame_size), 0.0);
          sp = base + static_cast<std::size_t>(fn->frame_size);
          code = fn->code.data();
          pc = 0;
          break;
        }
        case FnOp::ret: {
          const double result = s[sp - 1];
          if (depth == 0) return result;
          const Frame f = frames_.data()[--depth];
          sp = base;
          s[sp++] = result;
          fn = f.fn;
          base = f.base;
          pc = f.pc;
          code = fn->code.data();
          break;
        }
      }
    }
  }

 private:
  struct Frame {
    const FunctionValue* fn;   // the caller
    std::size_t pc;            // resume position in the caller
    std::size_t base;          // the caller's frame
  };
  InlineBuffer<double, 256> stack_;
  InlineBuffer<Frame, 16> frames_;
};

}  // namespace

std::string FunctionValue::description() const {
  std::string what;
  switch (kind) {
    case Kind::expression: what = "the function"; break;
    case Kind::internal: {
      const InternalFunctionInfo& info = internal_function_info(internal_id);
      return "the internal function " + std::string(info.name) + " (internal(" + std::to_string(internal_id) + "))";
    }
    case Kind::transform: what = "the transform function"; break;
    case Kind::pigment: what = "the pigment function"; break;
    case Kind::pattern: what = "the pattern function"; break;
    case Kind::spline: what = "the spline function"; break;
  }
  if (!name.empty()) what += " '" + name + "'";
  if (loc.file) what += " (written at " + loc.to_string() + ")";
  // A pattern function the renderer was asked about and cannot evaluate: the part of its pattern it refuses.
  if ((kind == Kind::pattern || kind == Kind::pigment) && refusal) {
    std::string part = refusal->name;
    if (refusal->loc.file && refusal->loc.to_string() != loc.to_string())
      part += " (at " + refusal->loc.to_string() + ")";
    what = part + " in " + what;
  }
  return what;
}

std::optional<std::string> unevaluable_part(const FunctionValue& f) {
  switch (f.kind) {
    case FunctionValue::Kind::internal:
      if (internal_function_info(f.internal_id).evaluable) return std::nullopt;
      return f.description();
    case FunctionValue::Kind::transform:
    case FunctionValue::Kind::spline: return std::nullopt;
    case FunctionValue::Kind::pigment:
      if (f.colour || f.prepared_pigment) return std::nullopt;
      return f.description();
    case FunctionValue::Kind::pattern:
      if (f.pattern) return std::nullopt;
      return f.description();
    case FunctionValue::Kind::expression:
      for (const FnInstr& in : f.code) {
        if (in.op == FnOp::unsupported) return f.callees[static_cast<std::size_t>(in.a)]->description();
        if (in.op == FnOp::call)
          if (auto part = unevaluable_part(*f.callees[static_cast<std::size_t>(in.a)])) return part;
      }
      return std::nullopt;
    default: return f.description();
  }
}

double evaluate_function(const FunctionValue& f, const double* args, double* vector_out, int noise_generator,
                         std::uint64_t* steps_left) {
  if (f.kind != FunctionValue::Kind::expression) {
    double out[5] = {0, 0, 0, 0, 0};
    evaluate_native(f, args, noise_generator, out);
    if (vector_out) std::copy(out, out + 5, vector_out);
    return out[0];
  }
  Machine machine;
  return machine.run(f, args, noise_generator, steps_left);
}

}  // namespace povtrace::sdl

// User-defined functions of the `function { … }` sub-language (povray-sdl-and-geometry.md §6): what
// `#declare F = function(a, b) { … }` stores, and the evaluator that runs it.
//
// A function body is parsed into an expression tree, folded the way POV-Ray's function compiler folds it (so
// results match POV-Ray's to the last bit: `x/10` is evaluated as `x*0.1`, `pow(x,3)` as `x*x*x`, constants in a
// chain of `+` are added first), then compiled into a flat program for a small stack machine. Calls between
// functions run on an explicit frame stack, never on the C++ stack, so evaluation depth is bounded only by the
// limit below (function_vm.cpp).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/description.hpp"
#include "scene/pattern_evaluator.hpp"
#include "scene/source_location.hpp"
#include "runtime/splines.hpp"
#include "scene/vecmath.hpp"

namespace povtrace::sdl {

struct FunctionValue;

// One instruction of a compiled function body. Operands are on a value stack; `a`, `b`, `c` are slot indices,
// jump targets, counts or selectors, `k` an immediate constant.
enum class FnOp : std::uint8_t {
  konst,        // push k
  load,         // push frame[a]
  add, sub, mul, div,
  addk, subk, mulk,   // top op= k
  neg,
  sqr,          // top = top*top
  pow,          // top = pow(second, top)
  pow_seq,      // top = top^a (a in 2…8) by POV-Ray's sequence of multiplications; a = 0: top = 1
  cmp,          // comparison a (FnCompare), result 1 or 0
  logic_and, logic_or,
  min2, max2,   // POV-Ray's min/max step (NaN handling of its compare-and-branch)
  math1,        // top = FnMath1 a (top)
  math2,        // top = FnMath2 a (second, top)
  jump,         // pc = a
  select,       // pop c: c < 0 → a, c > 0 or NaN → c, c == 0 → b
  loop_test,    // pop end, pop i: leave to a unless i <= end
  store,        // frame[a] = pop
  accumulate,   // frame[a] = frame[a] + pop (b == 0) or frame[a] * pop (b == 1)
  call,         // call callees[a] with the top b values as its parameters
  internal,     // evaluate internal function a on the top b values
  vector_call,  // callees[a] is a transform or pigment function: replace its arguments on the stack by
                // component b of its result (0…4; 5 the gray value, 6 the hf value)
  unsupported,  // callees[a] cannot be evaluated: a runtime error naming it
  ret,
};

enum class FnCompare : std::uint8_t { eq, ne, lt, le, gt, ge };
enum class FnMath1 : std::uint8_t {
  sin, cos, tan, asin, acos, atan, sinh, cosh, tanh, asinh, acosh, atanh, floor, ceil, sqrt, exp, ln, log,
  int_, abs
};
enum class FnMath2 : std::uint8_t { atan2, mod, div };

struct FnInstr {
  FnOp op = FnOp::ret;
  std::uint8_t b = 0;
  int a = 0;
  int c = 0;
  double k = 0;
};

struct FunctionValue {
  enum class Kind { expression, internal, transform, pigment, pattern, spline };
  Kind kind = Kind::expression;
  std::string name;                // the identifier it was first declared as, for messages ("" if none)
  SourceLoc loc;                   // where `function` was written
  int parameter_count = 3;         // what a call must pass
  int return_size = 0;             // 0 for a float function; 3 transform, 5 pigment, 2…5 spline
  int internal_id = -1;            // Kind::internal: POV-Ray's internal(N)

  // Kind::expression: the compiled body.
  std::vector<FnInstr> code;
  std::vector<std::shared_ptr<const FunctionValue>> callees;   // functions the body calls (kept alive)
  int frame_size = 0;              // parameters, then the loop variables of sum()/prod()
  int max_stack = 0;               // operand stack the body needs beyond its frame

  Matrix transform;                // Kind::transform
  std::optional<Colour> colour;    // Kind::pigment when the pigment is a plain colour
  std::shared_ptr<const Pigment> pigment;   // Kind::pigment: the pigment; Kind::pattern: the pattern block
                                            // (the renderer evaluates patterns)
  // Kind::pattern: the pattern made ready by ParseOptions::pattern_evaluator; null without an evaluator or when
  // the pattern cannot be evaluated, and then `refusal` names what is refused (nothing without an evaluator).
  std::shared_ptr<const PreparedPattern> pattern;
  // Kind::pigment other than a plain colour: the pigment made ready the same way, or null and `refusal` says why.
  std::shared_ptr<const PreparedPigment> prepared_pigment;
  Unsupported refusal;
  std::shared_ptr<const SplineValue> spline;   // Kind::spline: its one parameter is the spline's t

  // What the function is called in an "unsupported" message.
  std::string description() const;
};

// A function that cannot be evaluated (noise, patterns) or evaluation nested too deeply. The SDL call
// site turns it into a ParseError at the call.
class FunctionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Evaluates `f` on `args` (exactly f.parameter_count values). A float function returns its value; a vector
// function writes its return_size components to `vector_out` (which must hold 5) and returns the first.
// `noise_generator` is the scene's (1, 2 or 3) as POV-Ray reads it when the function runs: f_noise3d and the
// pattern and pigment functions use it, in `f` and in every function it calls. The parser passes the one in force
// when it evaluates, the renderer the scene's global_settings one.
// `steps_left`, if given, bounds the work: each sum()/prod() iteration and each call takes one step, and a
// FunctionError is thrown when none are left (ParseOptions::max_tokens: every parse must end).
double evaluate_function(const FunctionValue& f, const double* args, double* vector_out, int noise_generator,
                         std::uint64_t* steps_left = nullptr);

// The first part of `f` that evaluate_function would refuse (a noise-based internal function, a pattern…), as its description(); nothing when f can be evaluated everywhere. Lets a shape that evaluates f while
// rendering (isosurface) be refused by name when it is parsed.
std::optional<std::string> unevaluable_part(const FunctionValue& f);

// POV-Ray's internal functions (functions.inc: `function { internal(N) }`, N = 0…78).
constexpr int kInternalFunctionCount = 79;
struct InternalFunctionInfo {
  const char* name;       // functions.inc's name, e.g. "f_sphere"
  int parameter_count;    // x, y, z plus the extra parameters
  bool evaluable;         // false: needs a pattern
};
const InternalFunctionInfo& internal_function_info(int id);
// Evaluates internal function `id` (evaluable) on p[0…parameter_count-1]; may modify p. `scene_noise_generator`
// is the scene's noise_generator (1, 2 or 3), which f_noise3d uses.
double evaluate_internal_function(int id, double* p, int scene_noise_generator);

}  // namespace povtrace::sdl

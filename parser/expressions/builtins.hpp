// SDL's built-in functions as both expression engines call them (expressions.cpp, functions.cpp,
// expression_programs.cpp): the float functions with their argument counts and checks, and the names of the
// functions that return a string.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string_view>

namespace povtrace::sdl {

// The float arguments of a built-in call, on the stack (expressions in loops call built-ins millions of times).
struct CallArguments {
  static constexpr std::size_t kMax = 64;   // the most any built-in takes (min, max, bitwise_*)
  std::array<double, kMax> values;
  std::size_t count = 0;
  std::size_t size() const { return count; }
  const double* begin() const { return values.data(); }
  const double* end() const { return values.data() + count; }
  double operator[](std::size_t i) const { return values[i]; }
  void push_back(double v) { values[count++] = v; }   // callers stop at max_args ≤ kMax
};

// Which of POV-Ray's argument checks a built-in float function has (functions.cpp domain_error): known with the
// function, so that a call need not compare its name against each checked one.
enum class FloatDomain : std::uint8_t {
  any,             // no check
  non_negative,    // sqrt
  positive,        // ln, log
  not_both_zero,   // pow, atan2
  divisor,         // mod, div: the second argument is not 0
  unit             // acos, asin: |x| > 1 warns and is clamped
};

// A built-in float function (functions.cpp): its argument counts, its value and its argument check.
struct FloatFunction {
  std::size_t min_args, max_args;
  double (*eval)(const CallArguments&);   // a plain function: no std::function call per evaluation
  FloatDomain domain = FloatDomain::any;
};
const FloatFunction* find_float_function(std::string_view name);   // nullptr: no such built-in
// What parse_function_call gives for the built-in `name` with these arguments, or nullopt where it would report
// an error or warn instead (a domain error, acos(2), an infinite result): the expression programs call through here.
std::optional<double> quiet_float_call(const FloatFunction& f, const CallArguments& args);

// concat, str, chr, …: a call of one of these starts a string (not a float) expression.
inline bool is_string_function(std::string_view name) {
  static const std::string_view fns[] = {"concat", "str", "chr", "substr", "strupr", "strlwr", "vstr",
                                         "datetime"};
  for (auto f : fns)
    if (name == f) return true;
  return false;
}

}  // namespace povtrace::sdl

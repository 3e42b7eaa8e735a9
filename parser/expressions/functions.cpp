// Primary expressions and the built-in float/vector functions of POV-Ray 3.7 (povray-sdl-and-geometry.md §5).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <unordered_map>

#include "parser/expressions/int_cast.hpp"
#include "parser/expressions/expression_parser.hpp"
#include "parser/interpreter.hpp"
#include "runtime/noise.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
using Args = CallArguments;

double degrees_to_radians(double d) { return d * M_PI / 180.0; }

// int() and div() truncate toward zero. POV-Ray goes through an integer, so a result of zero is +0:
// int(-0.3) prints as "0.000000", not "-0.000000" as std::trunc's -0 would.
double truncated(double d) {
  const double t = std::trunc(d);
  return t == 0 ? 0.0 : t;
}

// Hashed: every call of a built-in looks its name up here (a tree of 33 names was 5 string comparisons).
const std::unordered_map<std::string_view, FloatFunction>& float_functions() {
  static const std::unordered_map<std::string_view, FloatFunction> table = {
      {"abs", {1, 1, [](const Args& a) { return std::fabs(a[0]); }}},
      {"acos", {1, 1, [](const Args& a) { return std::acos(std::clamp(a[0], -1.0, 1.0)); }, FloatDomain::unit}},
      {"asin", {1, 1, [](const Args& a) { return std::asin(std::clamp(a[0], -1.0, 1.0)); }, FloatDomain::unit}},
      {"atan", {1, 1, [](const Args& a) { return std::atan(a[0]); }}},
      {"atan2", {2, 2, [](const Args& a) { return std::atan2(a[0], a[1]); }, FloatDomain::not_both_zero}},
      {"sin", {1, 1, [](const Args& a) { return std::sin(a[0]); }}},
      {"cos", {1, 1, [](const Args& a) { return std::cos(a[0]); }}},
      {"tan", {1, 1, [](const Args& a) { return std::tan(a[0]); }}},
      {"sinh", {1, 1, [](const Args& a) { return std::sinh(a[0]); }}},
      {"cosh", {1, 1, [](const Args& a) { return std::cosh(a[0]); }}},
      {"tanh", {1, 1, [](const Args& a) { return std::tanh(a[0]); }}},
      {"asinh", {1, 1, [](const Args& a) { return std::asinh(a[0]); }}},
      {"acosh", {1, 1, [](const Args& a) { return std::acosh(a[0]); }}},
      {"atanh", {1, 1, [](const Args& a) { return std::atanh(a[0]); }}},
      {"exp", {1, 1, [](const Args& a) { return std::exp(a[0]); }}},
      {"sqrt", {1, 1, [](const Args& a) { return std::sqrt(a[0]); }, FloatDomain::non_negative}},
      {"ln", {1, 1, [](const Args& a) { return std::log(a[0]); }, FloatDomain::positive}},
      {"log", {1, 1, [](const Args& a) { return std::log10(a[0]); }, FloatDomain::positive}},
      {"pow", {2, 2, [](const Args& a) { return std::pow(a[0], a[1]); }, FloatDomain::not_both_zero}},
      {"floor", {1, 1, [](const Args& a) { return std::floor(a[0]); }}},
      {"ceil", {1, 1, [](const Args& a) { return std::ceil(a[0]); }}},
      {"int", {1, 1, [](const Args& a) { return truncated(a[0]); }}},
      {"div", {2, 2, [](const Args& a) { return truncated(a[0] / a[1]); }, FloatDomain::divisor}},
      {"mod", {2, 2, [](const Args& a) { return std::fmod(a[0], a[1]); }, FloatDomain::divisor}},
      {"degrees", {1, 1, [](const Args& a) { return a[0] * 180.0 / M_PI; }}},
      {"radians", {1, 1, [](const Args& a) { return degrees_to_radians(a[0]); }}},
      {"min", {1, 64, [](const Args& a) { return *std::min_element(a.begin(), a.end()); }}},
      {"max", {1, 64, [](const Args& a) { return *std::max_element(a.begin(), a.end()); }}},
      {"select", {3, 4, [](const Args& a) {
         if (a.size() == 3) return a[0] < 0 ? a[1] : a[2];
         return a[0] < 0 ? a[1] : (a[0] == 0 ? a[2] : a[3]);
       }}},
      {"bitwise_and", {2, 64, [](const Args& a) {
         long long r = saturating_cast<long long>(a[0]);
         for (std::size_t i = 1; i < a.size(); ++i) r &= saturating_cast<long long>(a[i]);
         return static_cast<double>(r);
       }}},
      {"bitwise_or", {2, 64, [](const Args& a) {
         long long r = saturating_cast<long long>(a[0]);
         for (std::size_t i = 1; i < a.size(); ++i) r |= saturating_cast<long long>(a[i]);
         return static_cast<double>(r);
       }}},
      {"bitwise_xor", {2, 64, [](const Args& a) {
         long long r = saturating_cast<long long>(a[0]);
         for (std::size_t i = 1; i < a.size(); ++i) r ^= saturating_cast<long long>(a[i]);
         return static_cast<double>(r);
       }}},
  };
  return table;
}

// Domain checks POV-Ray reports as errors (§5): whether the arguments fail the function's, and the message.
bool outside_domain(FloatDomain d, const Args& a) {
  switch (d) {
    case FloatDomain::any:
    case FloatDomain::unit: return false;   // a warning, not an error
    case FloatDomain::non_negative: return a[0] < 0;
    case FloatDomain::positive: return a[0] <= 0;
    case FloatDomain::not_both_zero: return a[0] == 0 && a[1] == 0;
    case FloatDomain::divisor: return a[1] == 0;
  }
  return false;
}

std::string domain_error(std::string_view name, FloatDomain d) {
  switch (d) {
    case FloatDomain::non_negative: return std::string(name) + " of a negative number";
    case FloatDomain::positive: return std::string(name) + " of a number that is not positive";
    case FloatDomain::not_both_zero: return std::string(name) + "(0, 0) is undefined";
    case FloatDomain::divisor: return std::string(name) + " by zero";
    default: return {};
  }
}
}  // namespace

CallArguments ExpressionParser::parse_call_arguments(const Token& name, std::size_t min_args, std::size_t max_args) {
  // Not expect(): its message would be built on every call of every built-in function. A plain '(' or ')' ahead is
  // taken where it stands, without making its Token (what next() would return, unchanged).
  if (plain_symbol(plain_ahead(), '(')) consume_plain();
  else if (const Token open = next(); !open.is("(")) fail_expected(open, "'(' after '" + std::string(name.text) + "'");
  CallArguments args;
  // Single-argument functions take a full-level expression (§5 "Two levels").
  if (max_args == 1) {
    args.push_back(parse_float_full());
  } else {
    // Commas between arguments are optional (POV-Ray's Parse_Comma) for the required arguments; optional
    // extra arguments (min/max beyond the first, select's fourth) need their comma, as in POV-Ray.
    for (std::size_t i = 0; i < min_args; ++i) {
      if (i > 0) accept(",");
      args.push_back(parse_float());
    }
    while (args.size() < max_args && accept(",")) args.push_back(parse_float());
  }
  if (plain_symbol(plain_ahead(), ')')) consume_plain();
  else if (const Token close = next(); !close.is(")"))
    fail_expected(close, "',' or ')' in the arguments of " + std::string(name.text));
  if (args.size() < min_args || args.size() > max_args)
    fail_at(name, std::string(name.text) + " takes " +
                      (min_args == max_args ? std::to_string(min_args) : "at least " + std::to_string(min_args)) +
                      " argument(s), found " + std::to_string(args.size()));
  return args;
}

bool ExpressionParser::is_float_function(std::string_view name) { return float_functions().count(name) > 0; }

const FloatFunction* find_float_function(std::string_view name) {
  const auto it = float_functions().find(name);
  return it == float_functions().end() ? nullptr : &it->second;
}

std::optional<double> quiet_float_call(const FloatFunction& f, const CallArguments& args) {
  // The checks of parse_function_call below, in its order; any that would speak declines.
  if (outside_domain(f.domain, args)) return std::nullopt;
  if (f.domain == FloatDomain::unit && std::fabs(args[0]) > 1.0) return std::nullopt;
  const double value = f.eval(args);
  if (!std::isfinite(value) && std::isfinite(args[0])) return std::nullopt;
  return value;
}

Numeric ExpressionParser::parse_function_call(const Token& name) {
  const std::string_view n = name.text;
  auto it = float_functions().find(n);
  if (it != float_functions().end()) {
    Args args = parse_call_arguments(name, it->second.min_args, it->second.max_args);
    if (outside_domain(it->second.domain, args)) fail_at(name, domain_error(n, it->second.domain));
    // POV-Ray warns "Domain error in acos/asin" and goes on with the clamped argument.
    if (it->second.domain == FloatDomain::unit && std::fabs(args[0]) > 1.0)
      warn(name.loc, "domain error in " + std::string(n));
    const double value = it->second.eval(args);
    // A result that is not a number or is infinite (pow(0, -1), exp(1000)) goes on, as in POV-Ray, but is named
    // where it is made: it would otherwise surface far away as a missing object or a black pixel.
    if (!std::isfinite(value) && std::isfinite(args[0]))
      warn(name.loc, std::string(n) + " gives " + (std::isnan(value) ? "a value that is not a number" : "an infinite value"));
    return Numeric::scalar(value);
  }
  auto vector_arg = [&](bool first) {
    if (!first) accept(",");   // optional between arguments, as POV-Ray's Parse_Comma
    return parse_vector();
  };
  if (n == "vlength" || n == "vnormalize") {
    expect("(", "");
    Vec3 v = vector_arg(true);
    expect(")", "");
    if (n == "vlength") return Numeric::scalar(length(v));
    if (length(v) == 0) { warn(name.loc, "vnormalize of a zero vector gives <0,0,0>"); return Numeric::vector({}); }
    return Numeric::vector(normalize(v));
  }
  if (n == "vdot" || n == "vcross" || n == "vrotate") {
    expect("(", "");
    Vec3 a = vector_arg(true), b = vector_arg(false);
    expect(")", "");
    if (n == "vdot") return Numeric::scalar(dot(a, b));
    if (n == "vcross") return Numeric::vector(cross(a, b));
    return Numeric::vector(Matrix::rotation(b).vector(a));
  }
  if (n == "vaxis_rotate") {
    expect("(", "");
    Vec3 v = vector_arg(true), axis = normalize(vector_arg(false));
    accept(",");
    const double angle = degrees_to_radians(parse_float());
    expect(")", "");
    // Same sense as `rotate` (vaxis_rotate(x, y, 90) = -z, §5): Rodrigues' formula as it stands, since
    // cross(y, x) = -z.
    const double c = std::cos(angle), s = std::sin(angle);
    return Numeric::vector(v * c + cross(axis, v) * s + axis * (dot(axis, v) * (1 - c)));
  }
  if (n == "vturbulence") {
    // vturbulence(lambda, omega, octaves, V): POV-Ray's DTurbulence at V, octaves truncated and kept in 1…10.
    expect("(", "");
    Turbulence t;
    t.lambda = static_cast<float>(parse_float());
    accept(",");
    t.omega = static_cast<float>(parse_float());
    accept(",");
    const double octaves = parse_float();
    t.octaves = std::isnan(octaves) ? 1 : static_cast<int>(std::clamp(std::trunc(octaves), 1.0, 10.0));
    const Vec3 v = vector_arg(false);
    accept(",");
    expect(")", "");
    return Numeric::vector(vector_turbulence(v, t));
  }
  if (n == "strlen" || n == "asc" || n == "val" || n == "file_exists") {
    expect("(", "");
    std::string s = parse_string();
    expect(")", "");
    if (n == "strlen") return Numeric::scalar(static_cast<double>(s.size()));
    if (n == "asc") return Numeric::scalar(s.empty() ? 0.0 : static_cast<unsigned char>(s[0]));
    if (n == "val") return Numeric::scalar(std::atof(s.c_str()));
    std::error_code ec;   // a name the file system rejects (too long, say) does not exist
    return Numeric::scalar(in().directives_.find_include(s) || std::filesystem::exists(s, ec) ? 1.0 : 0.0);
  }
  if (n == "strcmp") {
    expect("(", "");
    std::string a = parse_string();
    accept(",");
    std::string b = parse_string();
    expect(")", "");
    return Numeric::scalar(static_cast<double>(strcmp_value(a, b)));
  }
  if (n == "defined") {
    expect("(", " after 'defined'");
    return Numeric::scalar(in().arrays_.parse_defined_identifier() ? 1.0 : 0.0);
  }
  if (n == "dimensions" || n == "dimension_size") return in().arrays_.parse_dimensions(name);
  if (n == "inside" || n == "min_extent" || n == "max_extent") return in().object_queries_.parse_object_query(name);
  if (n == "now") {
    // Days since 2000-01-01 00:00 UTC (§5), with POV-Ray's microsecond resolution.
    const auto since_epoch = std::chrono::duration_cast<std::chrono::microseconds>(
        std::chrono::system_clock::now().time_since_epoch());
    constexpr double kY2kSeconds = 946684800.0;
    return Numeric::scalar((static_cast<double>(since_epoch.count()) * 1e-6 - kY2kSeconds) / 86400.0);
  }
  if (n == "trace") return in().object_queries_.parse_trace(name);
  if (n == "seed") {
    Args a = parse_call_arguments(name, 1, 1);
    in().rand_streams_.push_back(static_cast<std::uint32_t>(saturating_cast<long long>(a[0])));
    return Numeric::scalar(static_cast<double>(in().rand_streams_.size() - 1));
  }
  if (n == "rand") {
    Args a = parse_call_arguments(name, 1, 1);
    // Checked before the conversion: a negative, huge or NaN stream number does not convert to an index.
    if (!(a[0] >= 0 && a[0] < static_cast<double>(in().rand_streams_.size())))
      fail_at(name, "rand() of a stream that seed() did not create");
    const auto index = static_cast<std::size_t>(a[0]);
    // POV-Ray's generator (§5 "Random numbers"): a 32-bit LCG, result scaled to [0,1].
    std::uint32_t& s = in().rand_streams_[index];
    s = s * 1812433253u + 12345u;
    return Numeric::scalar(static_cast<double>(s) / 4294967295.0);
  }
  if (peek().is("(")) fail_unsupported(name, "the function '" + std::string(n) + "'");
  fail_expected(name, "a number, vector or expression");
}

Numeric ExpressionParser::parse_primary(const Token& t) {
  switch (t.kind) {
    case TokenKind::number: return Numeric::scalar(t.number);
    case TokenKind::symbol:
      if (t.is("(")) {
        Numeric n = parse_expression();
        skip_expected(')', " closing the parenthesis");
        return n;
      }
      if (t.is("<")) return parse_vector_literal(t);
      fail_expected(t, "a number, vector or expression");
    case TokenKind::identifier: break;
    default: fail_expected(t, "a number, vector or expression");
  }
  const std::string_view w = t.text;
  if (!reserved(t)) {
    const Value* v = lookup(t);
    if (!v) fail_at(t, "undeclared identifier '" + std::string(w) + "'");
    // An identifier holding a value povtrace parses but cannot use yet (a function, an array, …) is refused by
    // the name of that feature.
    if (const auto* opaque = std::get_if<Boxed<OpaqueValue>>(v))
      refuse_if_unsupported((*opaque)->feature, t.loc, "expression");
    if (const auto* fn = std::get_if<std::shared_ptr<const FunctionValue>>(v)) return in().functions_.call(t, *fn);
    if (const auto* s = std::get_if<Boxed<SplineValue>>(v)) return in().splines_.call(t, *s);
    if (!std::holds_alternative<Numeric>(*v))
      fail_at(t, "expected a number, vector or colour, found the " + value_type_name(*v) + " identifier '" +
                     std::string(w) + "'");
    return std::get<Numeric>(*v);
  }
  if (w == "x") return Numeric::vector({1, 0, 0});
  if (w == "y") return Numeric::vector({0, 1, 0});
  if (w == "z") return Numeric::vector({0, 0, 1});
  if (w == "t") { Numeric n; n.terms = 4; n.v[3] = 1; return n; }
  if (w == "u" || w == "v") { Numeric n; n.terms = 2; n.v[w == "u" ? 0 : 1] = 1; return n; }
  if (w == "pi") return Numeric::scalar(M_PI);
  if (w == "true" || w == "yes" || w == "on") return Numeric::scalar(1);
  if (w == "false" || w == "no" || w == "off") return Numeric::scalar(0);
  if (w == "version") return Numeric::scalar(language_version() / 100.0);
  // `clock` and `clock_on` are keywords (clock_delta is a declared identifier): POV-Ray's express.cpp.
  if (w == "clock") return Numeric::scalar(parse_options().clock.value_or(0.0));
  if (w == "clock_on") return Numeric::scalar(parse_options().clock ? 1.0 : 0.0);
  // rgb… and color start Parse_Colour, so overrides apply here too (`rgb <1,0,0> filter 0.5`, §5).
  if (w == "rgb" || w == "rgbf" || w == "rgbt" || w == "rgbft" || w.starts_with("srgb") || w == "color" ||
      w == "colour") {
    unget(t);
    return Numeric::from_colour(parse_colour());
  }
  return parse_function_call(t);
}

}  // namespace povtrace::sdl

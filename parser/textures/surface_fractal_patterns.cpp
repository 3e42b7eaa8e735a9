// The fractal patterns (mandel, julia, magnet) and slope, with their parameters, as POV-Ray 3.7's Parse_Pattern
// reads them (parser/parstxtr.cpp MANDEL_TOKEN, JULIA_TOKEN, MAGNET_TOKEN, SLOPE_TOKEN, EXTERIOR_TOKEN,
// INTERIOR_TOKEN, EXPONENT_TOKEN):
// - `mandel ITERATIONS`, `julia <u, v>, ITERATIONS`, `magnet 1|2 mandel ITERATIONS`, `magnet 1|2 julia <u, v>,
//   ITERATIONS`. Each resets exterior 1, 1, interior 0, 1 and exponent 2. Integers are (int) of the float.
// - `exponent N` (mandel, julia): 2…33; any other value warns and uses 2.
// - `exterior TYPE, FACTOR` (0…8) and `interior TYPE, FACTOR` (0…6); elsewhere they are errors.
// - `slope V` or `slope { [point_at] V [, LOW [, HIGH]] [altitude A [, LOW [, HIGH]]] }`: both lengths are kept
//   as weights summing to 1, the vectors normalised; an exact ± unit axis is remembered as a shortcut.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>

#include "scene/pov_vector_math.hpp"
#include "parser/interpreter.hpp"
#include "parser/textures/texture_parser.hpp"

namespace povtrace::sdl {

namespace {
bool is_fractal(PatternKind k) {
  return k == PatternKind::mandel || k == PatternKind::julia || k == PatternKind::magnet;
}

// ±(1 + axis) when v is exactly ± that unit axis (the first such axis), else 0.
int unit_axis(Vec3 v) {
  for (int i = 0; i < 3; ++i) {
    if (v[i] == 1.0) return i + 1;
    if (v[i] == -1.0) return -(i + 1);
  }
  return 0;
}
}  // namespace

void TextureParser::parse_fractal_pattern(const Token& keyword, Pigment& p) {
  FractalParams f;
  if (keyword.is("magnet")) {
    const Token number = peek();
    const int type = truncated_int(parse_float());
    const Token form = next();
    if (!form.is("mandel") && !form.is("julia"))
      fail_at(form, "Invalid magnet pattern found. Valid types are 'mandel' and 'julia'.");
    if (type != 1 && type != 2)
      fail_at(number, form.is("mandel") ? "Invalid magnet-mandel pattern type found. Valid types are 1 and 2."
                                        : "Invalid magnet-julia pattern type found. Valid types are 1 and 2.");
    f.magnet = type;
    f.exponent = 0;
    f.julia = form.is("julia");
  } else {
    f.julia = keyword.is("julia");
  }
  if (f.julia) {
    std::tie(f.coord_u, f.coord_v) = parse_uv_vector("(the julia pattern's complex constant)");
    accept(",");
  }
  const Token count = peek();
  f.iterations = truncated_int(parse_float());
  // POV-Ray reads a negative count as a huge unsigned one and leaves the value of every point undefined.
  if (f.iterations < 0) fail_at(count, "the number of iterations of a fractal pattern must not be negative");
  p.pattern = keyword.is("mandel") ? PatternKind::mandel : keyword.is("julia") ? PatternKind::julia
                                                                                 : PatternKind::magnet;
  p.fractal = f;
}

bool TextureParser::try_fractal_parameter(const Token& t, Pigment& p) {
  const bool exterior = t.is("exterior"), interior = t.is("interior");
  if (exterior || interior) {
    if (!is_fractal(p.pattern))
      fail_at(t, "Keyword '" + std::string(t.text) + "' can only be used in a mandel, julia or magnet pattern.");
    const Token type_at = peek();
    const int type = truncated_int(parse_float());
    accept(",");
    const Token factor_at = peek();
    const double factor = parse_float();
    if (exterior) {
      if (type < 0 || type > 8)
        fail_at(type_at, "Invalid fractal pattern exterior type. Valid types are 0 to 8.");
      // Types 7 and 8 take the iteration count modulo (unsigned)factor or (unsigned)(1 + factor): POV-Ray divides by
      // zero there (and crashes) when that is 0.
      const double modulus = type == 7 ? factor : 1 + factor;
      if ((type == 7 || type == 8) &&
          (std::isnan(modulus) || static_cast<std::uint32_t>(static_cast<std::int64_t>(
                                      std::clamp(std::trunc(modulus), -4e18, 4e18))) == 0))
        fail_at(factor_at, "exterior type " + std::to_string(type) +
                               " takes the iteration count modulo the factor" + (type == 8 ? " + 1" : "") +
                               ", which must not be 0 once truncated to an unsigned integer");
      p.fractal.exterior_type = type;
      p.fractal.exterior_factor = factor;
    } else {
      if (type < 0 || type > 6)
        fail_at(type_at, "Invalid fractal pattern interior type. Valid types are 0 to 6.");
      p.fractal.interior_type = type;
      p.fractal.interior_factor = factor;
    }
    return true;
  }
  if (t.is("exponent")) {
    if (p.pattern != PatternKind::mandel && p.pattern != PatternKind::julia)
      fail_at(t, "Keyword 'exponent' can only be used in a mandel or julia pattern.");
    const int n = truncated_int(parse_float());
    if (n >= 2 && n <= 33) {
      p.fractal.exponent = n;
    } else {
      p.fractal.exponent = 2;
      warn(t.loc, std::string("Invalid ") + (p.pattern == PatternKind::julia ? "julia" : "mandel") +
                      " pattern exponent found. Supported exponents are 2 to 33. Using default exponent 2.");
    }
    return true;
  }
  return false;
}

void TextureParser::parse_slope_pattern(const Token& keyword, Pigment& p) {
  SlopeParams s;
  s.direction = {0, 0, 0};
  // `low, high` → low and high − low; equal non-zero ends are ignored with POV-Ray's warning.
  const auto range = [&](double& low, double& span, const char* what) {
    accept(",");
    low = optional_float(0.0);
    accept(",");
    span = optional_float(0.0);
    if (span != 0.0 && span == low) {
      low = span = 0.0;
      warn(keyword.loc, std::string("Zero ") + what + " range, ignoring.");
    } else {
      span -= low;
    }
  };
  if (!peek().is("{")) {
    s.direction = parse_vector();
  } else {
    const Token open = next();
    const NestingGuard guard(*this, open);
    if (peek().is("point_at")) {
      next();
      s.point_at = true;
    }
    s.direction = parse_vector();
    range(s.slope_low, s.slope_range, "slope");
    if (peek().is("altitude")) {
      const Token a = next();
      if (s.point_at) fail_at(a, "Keyword 'altitude' cannot be used with 'point_at' in slope pattern.");
      s.altitude = parse_vector();
      range(s.altitude_low, s.altitude_range, "gradient");
    }
    expect("}", " closing slope { }");
  }
  if (s.point_at) {
    s.slope_weight = 1.0;
    s.altitude_weight = 0.0;
  } else {
    double slope_len = length(s.direction), altitude_len = length(s.altitude);
    if (slope_len != 0.0) s.direction = pov_normalized(s.direction);
    if (altitude_len != 0.0) s.altitude = pov_normalized(s.altitude);
    const double total = slope_len + altitude_len;
    if (total == 0.0) fail_at(keyword, "Zero length for both slope and gradient.");
    s.slope_weight = slope_len / total;
    s.altitude_weight = 1.0 - s.slope_weight;
    s.slope_axis = unit_axis(s.direction);
    s.altitude_axis = unit_axis(s.altitude);
  }
  p.pattern = PatternKind::slope;
  p.slope = s;
}

}  // namespace povtrace::sdl

// SDL `spline { … }` values and their evaluation, as POV-Ray 3.7 does it (Parse_Spline in express.cpp,
// Insert_Spline_Entry and Get_Spline_Val in backend/math/splines.cpp). Pure math: no parser types, so the
// renderer or a test can evaluate a spline without parsing one.
#pragma once

#include <array>
#include <vector>

namespace povtrace::sdl {

// The four interpolations. `cubic_spline` is POV-Ray's Catmull-Rom spline, `natural_spline` the interpolating
// cubic with zero second derivative at both ends.
enum class SplineType { linear, quadratic, cubic, natural };

// One `T, V` entry: POV-Ray keeps every entry's value as five components, whatever the vector's size.
struct SplineEntry {
  double t = 0;
  std::array<double, 5> value{};
};

struct SplineValue {
  SplineType type = SplineType::linear;
  std::vector<SplineEntry> entries;   // ascending t, no t twice (insert_spline_entry keeps them so)
  int terms = 2;                      // components a call returns: the most any entry gave, at least 2
  // The natural spline's second derivative at each entry, per component: solved once the entries are final
  // (solve_natural_spline), so that any call may ask for natural interpolation (`S(t, natural_spline)`).
  std::vector<std::array<double, 5>> second_derivatives;
};

// Adds an entry where its t belongs. A t already present replaces that entry's value, except the largest t,
// whose second value is dropped: POV-Ray 3.7 writes it one slot past the last entry, where it is lost (checked
// with POV-Ray 3.7.0.10: spline { 0,<0> … 2,<2> 2,<9> } still gives <2> at 2). Invalidates second_derivatives.
void insert_spline_entry(SplineValue& s, double t, const std::array<double, 5>& value);

// Fills second_derivatives from the entries (at least one).
void solve_natural_spline(SplineValue& s);

// The spline's value at t interpolated as `type` (all five components). Outside the entries' range the value
// is held at an end value (the cubic spline's ends are its second and next-to-last entries), and a spline with
// too few entries for its type falls back as POV-Ray's does.
std::array<double, 5> evaluate_spline(const SplineValue& s, SplineType type, double t);

}  // namespace povtrace::sdl

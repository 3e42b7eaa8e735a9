// Spline interpolation reproducing POV-Ray 3.7's results (backend/math/splines.cpp, read for its behaviour):
// which entries each type uses near the ends, what it returns outside the entries' range, and how it falls
// back when there are too few entries. The values were checked against POV-Ray 3.7.0.10 (tests/parser/
// spline_test.cpp).
#include "runtime/splines.hpp"

#include <cmath>
#include <cstddef>

namespace povtrace::sdl {

namespace {
using Components = std::array<double, 5>;

// The index of the entry that ends t's segment: 0 when t is at or before the first entry, entries.size() when
// at or after the last, else the first entry whose t is not below t. POV-Ray finds it by bisection, which for a
// NaN t (every comparison false) ends at entry 1; NaN then propagates through the interpolation as it does there.
std::size_t segment_end(const std::vector<SplineEntry>& e, double t) {
  const std::size_t n = e.size();
  if (n == 0 || t <= e.front().t) return 0;
  if (t >= e.back().t) return n;
  if (std::isnan(t)) return n == 1 ? 0 : 1;
  std::size_t below = 0, above = n - 1;   // e[below].t < t <= e[above].t
  while (above - below > 1) {
    const std::size_t mid = below + (above - below) / 2;
    if (t > e[mid].t) below = mid;
    else above = mid;
  }
  return above;
}

double slope(const SplineEntry& a, const SplineEntry& b, int k) {
  return (b.value[k] - a.value[k]) / (b.t - a.t);
}

double linear(const SplineEntry& a, const SplineEntry& b, int k, double t) {
  return a.value[k] + (t - a.t) * (b.value[k] - a.value[k]) / (b.t - a.t);
}

// The parabola through three entries, evaluated as a*t² + b*t + c: POV-Ray works with these coefficients of t
// (not with a form centred on an entry), so its rounding for large t is reproduced closely, though not to the
// last bit: our coefficients are factored differently (on 60 random points they differed from POV-Ray 3.7's by
// up to 4e-14; linear, cubic and natural splines matched to all 16 printed digits).
double quadratic(const SplineEntry& e1, const SplineEntry& e2, const SplineEntry& e3, int k, double t) {
  const double t1 = e1.t, t2 = e2.t, t3 = e3.t;
  const double v1 = e1.value[k], v2 = e2.value[k], v3 = e3.value[k];
  const double n = (t2 - t1) * (t3 - t1) * (t3 - t2);
  const double a = (v1 * (t3 - t2) + v2 * (t1 - t3) + v3 * (t2 - t1)) / n;
  const double b = (v1 * (t2 * t2 - t3 * t3) + v2 * (t3 * t3 - t1 * t1) + v3 * (t1 * t1 - t2 * t2)) / n;
  const double c = (v1 * t2 * t3 * (t3 - t2) + v2 * t1 * t3 * (t1 - t3) + v3 * t1 * t2 * (t2 - t1)) / n;
  return (a * t + b) * t + c;
}

// Segment j..j+1 of the natural cubic, from the entries' values and second derivatives m, in powers of (t - t_j).
double natural(const SplineValue& s, std::size_t j, int k, double t) {
  const SplineEntry& a = s.entries[j];
  const SplineEntry& b = s.entries[j + 1];
  const double ma = s.second_derivatives[j][k], mb = s.second_derivatives[j + 1][k];
  const double h = b.t - a.t, d = t - a.t;
  // Summed in POV-Ray's order: a knot's value then comes out with POV-Ray's rounding (even the sign of a zero).
  const double cubic_part = ma / 2 + d * (mb - ma) / (6 * h);
  const double first_part = -(h / 6) * (mb + 2 * ma) + (b.value[k] - a.value[k]) / h + d * cubic_part;
  return a.value[k] + d * first_part;
}

// Segment j..j+1 of POV-Ray's Catmull-Rom spline: a cubic Hermite segment whose tangent at each end is the mean
// of the slopes of the two segments meeting there, scaled to this segment's length (uneven spacing allowed).
double catmull_rom(const std::vector<SplineEntry>& e, std::size_t j, int k, double t) {
  const double dt = e[j + 1].t - e[j].t;
  const double u = (t - e[j].t) / dt;
  const double middle = slope(e[j], e[j + 1], k);
  const double tangent0 = (slope(e[j - 1], e[j], k) + middle) / 2 * dt;
  const double tangent1 = (slope(e[j + 1], e[j + 2], k) + middle) / 2 * dt;
  // The Hermite basis, each product in POV-Ray's order (3*u*u is not 3*(u*u) to the last bit).
  return e[j].value[k] * (2 * u * u * u - 3 * u * u + 1) + e[j + 1].value[k] * (3 * u * u - 2 * u * u * u) +
         tangent0 * (u * u * u - 2 * u * u + u) + tangent1 * (u * u * u - u * u);
}

// One component at t, given i = segment_end(t). `last` is the index of the last entry (at least 1).
double component(const SplineValue& s, SplineType type, std::size_t i, std::size_t last, int k, double t) {
  const std::vector<SplineEntry>& e = s.entries;
  if (type == SplineType::cubic) {
    // Catmull-Rom needs an entry on each side of its segment: two entries give their mean everywhere, and the
    // value is held at the second entry before it and at the next-to-last one after.
    if (last == 1) return (e[0].value[k] + e[1].value[k]) / 2;
    if (i < 2) return e[1].value[k];
    if (i >= last) return e[last - 1].value[k];
    return catmull_rom(e, i - 1, k, t);
  }
  // The other types hold the first and last values outside the entries' range.
  if (i == 0) return e[0].value[k];
  if (i > last) return e[last].value[k];
  switch (type) {
    case SplineType::quadratic:
      if (last == 1) return linear(e[0], e[1], k, t);   // two entries: a line
      // The parabola through the segment's entries and the one before; the first segment uses the one after.
      if (i == 1) return quadratic(e[0], e[1], e[2], k, t);
      return quadratic(e[i - 2], e[i - 1], e[i], k, t);
    case SplineType::natural: return natural(s, i - 1, k, t);
    default: return linear(e[i - 1], e[i], k, t);
  }
}
}  // namespace

void insert_spline_entry(SplineValue& s, double t, const Components& value) {
  s.second_derivatives.clear();
  std::vector<SplineEntry>& e = s.entries;
  const std::size_t i = segment_end(e, t);
  if (i < e.size() && e[i].t == t) {
    e[i].value = value;
    return;
  }
  if (i == e.size() && !e.empty() && e.back().t == t) return;   // lost in POV-Ray 3.7 (see the header)
  e.insert(e.begin() + static_cast<std::ptrdiff_t>(i), SplineEntry{t, value});
}

void solve_natural_spline(SplineValue& s) {
  const std::vector<SplineEntry>& e = s.entries;
  const std::size_t n = e.size();
  // Zero at both ends; with fewer than three entries that is all, and the natural spline is a line.
  s.second_derivatives.assign(n, Components{});
  if (n < 3) return;
  std::vector<double> diagonal(n), rhs(n);
  for (int k = 0; k < 5; ++k) {
    // The tridiagonal system h[r-1]·m[r-1] + 2(h[r-1]+h[r])·m[r] + h[r]·m[r+1] = 6(slope[r] - slope[r-1]) for the
    // inner entries r, by forward elimination and back substitution.
    for (std::size_t r = 1; r + 1 < n; ++r) {
      const double h_before = e[r].t - e[r - 1].t, h_after = e[r + 1].t - e[r].t;
      diagonal[r] = 2 * (h_before + h_after);
      rhs[r] = 6 * (slope(e[r], e[r + 1], k) - slope(e[r - 1], e[r], k));
      if (r > 1) {
        diagonal[r] -= h_before * h_before / diagonal[r - 1];
        rhs[r] -= h_before * rhs[r - 1] / diagonal[r - 1];
      }
    }
    for (std::size_t r = n - 2; r >= 1; --r) {
      const double h_after = e[r + 1].t - e[r].t;
      s.second_derivatives[r][k] = (rhs[r] - h_after * s.second_derivatives[r + 1][k]) / diagonal[r];
    }
  }
}

Components evaluate_spline(const SplineValue& s, SplineType type, double t) {
  Components out{};
  const std::vector<SplineEntry>& e = s.entries;
  if (e.empty()) return out;
  if (e.size() == 1) return e[0].value;   // one entry: its value everywhere, whatever the type
  if (type == SplineType::natural && s.second_derivatives.size() != e.size()) {   // not solved yet
    SplineValue solved = s;
    solve_natural_spline(solved);
    return evaluate_spline(solved, type, t);
  }
  const std::size_t last = e.size() - 1;
  const std::size_t i = segment_end(e, t);
  for (int k = 0; k < 5; ++k) out[k] = component(s, type, i, last, k, t);
  return out;
}

}  // namespace povtrace::sdl

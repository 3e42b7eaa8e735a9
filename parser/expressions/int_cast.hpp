// Floats used as integers: counts, widths, precisions, character codes, stream numbers, bit patterns. Converting a
// double that does not fit (or NaN) to an integer type is undefined behaviour in C++, and SDL values can be
// anything (`str(1, 1e300, 0)`): these truncate toward zero and saturate at the type's limits; NaN gives 0.
#pragma once

#include <cmath>
#include <limits>

namespace povtrace::sdl {

template <class Int> Int saturating_cast(double x) {
  if (std::isnan(x)) return 0;
  constexpr double lowest = static_cast<double>(std::numeric_limits<Int>::min());
  // max() may round up to a power of two (2^63 for 64 bits): values at or above it saturate.
  constexpr double highest = static_cast<double>(std::numeric_limits<Int>::max());
  if (x <= lowest) return std::numeric_limits<Int>::min();
  if (x >= highest) return std::numeric_limits<Int>::max();
  return static_cast<Int>(x);
}

}  // namespace povtrace::sdl

#include "app/region.hpp"

#include <cmath>
#include <cstdio>
#include <string>

namespace povtrace::app {
namespace {

// int(v) in POV-Ray truncates toward zero; values far outside int's range are out of the image anyway.
long truncated(double v) { return std::isfinite(v) && std::fabs(v) < 1e15 ? static_cast<long>(v) : -1; }

long resolve_start(std::optional<double> v, int size) {
  if (!v) return 0;
  if (*v >= 0.0 && *v < 1.0) return truncated(size * *v);
  return truncated(*v) - 1;
}

long resolve_end(std::optional<double> v, int size) {
  if (!v) return size - 1;
  if (*v >= 0.0 && *v <= 1.0) return truncated(size * *v) - 1;
  return truncated(*v) - 1;
}

std::string number(std::optional<double> v) {
  if (!v) return "unset";
  char text[32];
  std::snprintf(text, sizeof text, "%g", *v);
  return text;
}

}  // namespace

std::optional<image::PixelRect> resolve_region(const RegionOptions& o, int width, int height) {
  if (!o.start_row && !o.end_row && !o.start_column && !o.end_column) return std::nullopt;
  const long x0 = resolve_start(o.start_column, width), y0 = resolve_start(o.start_row, height);
  const long x1 = resolve_end(o.end_column, width), y1 = resolve_end(o.end_row, height);
  if (x0 < 0 || x0 >= width || y0 < 0 || y0 >= height) {
    throw UsageError("invalid start column or row (+SC" + number(o.start_column) + " +SR" + number(o.start_row) +
                     " in a " + std::to_string(width) + "x" + std::to_string(height) + " image)");
  }
  if (x1 < 0 || x1 >= width || y1 < 0 || y1 >= height) {
    throw UsageError("invalid end column or row (+EC" + number(o.end_column) + " +ER" + number(o.end_row) +
                     " in a " + std::to_string(width) + "x" + std::to_string(height) + " image)");
  }
  if (x1 < x0 || y1 < y0) {
    throw UsageError("invalid region: the end column or row is before the start (columns " + std::to_string(x0 + 1) +
                     "-" + std::to_string(x1 + 1) + ", rows " + std::to_string(y0 + 1) + "-" + std::to_string(y1 + 1) +
                     ")");
  }
  return image::PixelRect{static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1), static_cast<int>(y1)};
}

}  // namespace povtrace::app

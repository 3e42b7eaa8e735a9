#include "renderer/image/compare.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>

namespace povtrace::image {
namespace {

constexpr double infinity = std::numeric_limits<double>::infinity();
constexpr double heat_saturation = 16.0;  // the heat map's ramp ends (red) at this multiple of the threshold
constexpr double heat_min_blue = 0.3;     // the dimmest blue, so tiny differences are still visible

void check_same_size(const Image& a, const Image& b) {
  if (a.width == b.width && a.height == b.height) return;
  throw ImageError("image sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) + " vs " +
                   std::to_string(b.width) + "x" + std::to_string(b.height));
}

// The two images in the comparison space. Only an image that needs converting is copied.
class ComparedPair {
 public:
  ComparedPair(const Image& a, const Image& b) : a_(&a), b_(&b), channels_(a.has_alpha || b.has_alpha ? 4 : 3) {
    check_same_size(a, b);
    if (a.encoding == b.encoding) return;
    converted_ = to_linear(a.encoding == Encoding::encoded ? a : b);
    (a.encoding == Encoding::encoded ? a_ : b_) = &converted_;
  }
  ComparedPair(const ComparedPair&) = delete;
  ComparedPair& operator=(const ComparedPair&) = delete;

  int width() const { return a_->width; }
  int height() const { return a_->height; }
  int channels() const { return channels_; }

  // |b − a| for one channel of the pixel at row-major index `pixel`.
  double difference(std::size_t pixel, int channel) const {
    const double x = value(*a_, pixel, channel);
    const double y = value(*b_, pixel, channel);
    if (x == y) return 0.0;  // also equal infinities
    const double d = std::fabs(y - x);
    return std::isnan(d) ? infinity : d;
  }

  double largest_difference(std::size_t pixel) const {
    double largest = 0.0;
    for (int c = 0; c < channels_; ++c) largest = std::max(largest, difference(pixel, c));
    return largest;
  }

 private:
  static double value(const Image& image, std::size_t pixel, int channel) {
    if (channel == 3 && !image.has_alpha) return 1.0;
    return image.rgba[pixel * 4 + static_cast<std::size_t>(channel)];
  }

  const Image* a_;
  const Image* b_;
  int channels_;
  Image converted_;
};

struct ErrorSums {
  double squared = 0.0;
  double absolute = 0.0;

  void add(double d) {
    squared += d * d;
    absolute += d;
  }
};

void note_if_largest(CompareReport& report, double d, int x, int y, int channel) {
  if (!(d > report.max_abs_error)) return;
  report.max_abs_error = d;
  report.max_x = x;
  report.max_y = y;
  report.max_channel = channel;
}

void finish(CompareReport& report, const ErrorSums& sums, int channels) {
  const double values = static_cast<double>(report.pixel_count) * channels;
  if (values > 0) {
    report.rmse = std::sqrt(sums.squared / values);
    report.mean_abs_error = sums.absolute / values;
    report.share_over_threshold = static_cast<double>(report.pixels_over_threshold) / report.pixel_count;
  }
  report.psnr = report.rmse == 0.0 ? infinity : 20.0 * std::log10(1.0 / report.rmse);
}

using Rgb = std::array<float, 3>;

// Blue for differences up to the threshold, then green → yellow → red over [threshold, 16·threshold] (log).
Rgb heat_colour(double d, double threshold) {
  if (!(d > 0.0)) return {0.0f, 0.0f, 0.0f};
  if (d <= threshold) {
    return {0.0f, 0.0f, static_cast<float>(heat_min_blue + (1.0 - heat_min_blue) * std::min(1.0, d / threshold))};
  }
  double t = threshold > 0.0 ? std::log2(d / threshold) / std::log2(heat_saturation) : 1.0;
  t = std::clamp(std::isnan(t) ? 1.0 : t, 0.0, 1.0);
  if (t < 0.5) return {static_cast<float>(2.0 * t), 1.0f, 0.0f};
  return {1.0f, static_cast<float>(2.0 * (1.0 - t)), 0.0f};
}

void check_strip_inputs(const std::vector<const Image*>& images) {
  if (images.empty()) throw ImageError("side_by_side: no images");
  for (const Image* image : images) {
    if (image == nullptr) throw ImageError("side_by_side: null image");
    if (image->height != images.front()->height) throw ImageError("side_by_side: the images' heights differ");
  }
}

Encoding strip_encoding(const std::vector<const Image*>& images) {
  for (const Image* image : images) {
    if (image->encoding != images.front()->encoding) return Encoding::linear;
  }
  return images.front()->encoding;
}

void paste(Image& strip, const Image& image, int x0) {
  if (image.width == 0) return;
  for (int y = 0; y < image.height; ++y) {
    const float* row = image.pixel(0, y);
    std::copy(row, row + static_cast<std::size_t>(image.width) * 4, strip.pixel(x0, y));
  }
}

}  // namespace

Encoding comparison_encoding(const Image& a, const Image& b) {
  return a.encoding == b.encoding ? a.encoding : Encoding::linear;
}

CompareReport compare_images(const Image& a, const Image& b, double threshold) {
  const ComparedPair pair(a, b);
  CompareReport report;
  report.threshold = threshold;
  report.pixel_count = static_cast<std::size_t>(pair.width()) * pair.height();
  ErrorSums sums;
  for (std::size_t i = 0; i < report.pixel_count; ++i) {
    const int x = static_cast<int>(i % pair.width());
    const int y = static_cast<int>(i / pair.width());
    for (int c = 0; c < pair.channels(); ++c) {
      const double d = pair.difference(i, c);
      sums.add(d);
      note_if_largest(report, d, x, y, c);
    }
    if (pair.largest_difference(i) > threshold) ++report.pixels_over_threshold;
  }
  finish(report, sums, pair.channels());
  return report;
}

Image difference_heat_map(const Image& a, const Image& b, double threshold) {
  const ComparedPair pair(a, b);
  Image map(pair.width(), pair.height());
  map.encoding = Encoding::encoded;
  for (std::size_t i = 0; i < map.rgba.size() / 4; ++i) {
    const Rgb colour = heat_colour(pair.largest_difference(i), threshold);
    std::copy(colour.begin(), colour.end(), &map.rgba[i * 4]);
  }
  return map;
}

Image side_by_side(const std::vector<const Image*>& images) {
  check_strip_inputs(images);
  int width = 0;
  for (const Image* image : images) width += image->width;
  Image strip(width, images.front()->height);
  strip.encoding = strip_encoding(images);
  int x0 = 0;
  for (const Image* image : images) {
    strip.has_alpha = strip.has_alpha || image->has_alpha;
    paste(strip, image->encoding == strip.encoding ? *image : to_linear(*image), x0);
    x0 += image->width;
  }
  return strip;
}

}  // namespace povtrace::image

#include "renderer/image/display_encode.hpp"

#include <algorithm>
#include <cmath>

namespace povtrace::image {
namespace {

struct Rgba {
  double r, g, b, a;
};

double grey(const Rgba& c) { return grey_weight_r * c.r + grey_weight_g * c.g + grey_weight_b * c.b; }

// Raise alpha so that highlights on transparent surfaces survive un-premultiplying (pipeline §6).
Rgba raise_alpha_for_bright_colour(Rgba c) {
  const double g = grey(c);
  if (g > c.a) c.a = std::min(1.0, g);
  return c;
}

Rgba unpremultiply(const Rgba& c) {
  if (!(c.a > 0.0)) return {0.0, 0.0, 0.0, 0.0};
  return {c.r / c.a, c.g / c.a, c.b / c.a, c.a};
}

std::uint16_t quantise(double value, double max_code) {
  if (!(value > 0.0)) return 0;  // also NaN
  if (value > 1.0) value = 1.0;
  return static_cast<std::uint16_t>(std::floor(value * max_code + 0.5));
}

Rgba display_colour(const Image& image, const float* p, bool with_alpha) {
  const bool linear = image.encoding == Encoding::linear;
  Rgba c{p[0], p[1], p[2], image.has_alpha ? p[3] : 1.0};
  if (with_alpha) c = unpremultiply(linear ? raise_alpha_for_bright_colour(c) : c);
  if (linear) c = {srgb_encode(c.r), srgb_encode(c.g), srgb_encode(c.b), c.a};
  return c;
}

}  // namespace

std::vector<std::uint16_t> display_samples(const Image& image, int bits, bool with_alpha) {
  const double max_code = std::ldexp(1.0, bits) - 1.0;
  const std::size_t channels = with_alpha ? 4 : 3;
  std::vector<std::uint16_t> samples;
  samples.reserve(static_cast<std::size_t>(image.width) * image.height * channels);
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    const Rgba c = display_colour(image, &image.rgba[i], with_alpha);
    for (const double v : {c.r, c.g, c.b}) samples.push_back(quantise(v, max_code));
    if (with_alpha) samples.push_back(quantise(c.a, max_code));
  }
  return samples;
}

}  // namespace povtrace::image

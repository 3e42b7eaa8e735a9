#include "renderer/image/display_encode.hpp"

#include <algorithm>
#include <cmath>

#include "renderer/image/dither.hpp"

namespace povtrace::image {
namespace {

constexpr float zero_alpha_stand_in = 1.0e-6f;  // POV-Ray divides by this where alpha is 0

float grey(float r, float g, float b) { return r * grey_weight_r + g * grey_weight_g + b * grey_weight_b; }

float clip01(float v) { return std::clamp(v, 0.0f, 1.0f); }

unsigned quantise(float value, unsigned max_code) {
  if (!(value > 0.0f)) return 0;  // also NaN
  return static_cast<unsigned>(std::floor(clip01(value) * static_cast<float>(max_code) + 0.5f));
}

// One pixel's colour (1 or 3 values) and alpha before quantising.
struct PixelValues {
  float c[3];
  float alpha;
};

PixelValues pixel_values(const Image& image, const float* p, const SampleLayout& layout) {
  const bool linear = image.encoding == Encoding::linear;
  PixelValues v{{p[0], p[1], p[2]}, image.has_alpha ? p[3] : 1.0f};
  if (layout.grey) v.c[0] = grey(p[0], p[1], p[2]);
  if (!layout.alpha) return v;
  const float bright = layout.grey ? v.c[0] : grey(v.c[0], v.c[1], v.c[2]);
  // Raise alpha so that highlights on transparent surfaces survive un-premultiplying (pipeline §6).
  if (linear && bright > v.alpha) v.alpha = std::min(1.0f, bright);
  const float divisor = v.alpha == 0.0f ? zero_alpha_stand_in : v.alpha;
  for (float& c : v.c) c /= divisor;
  return v;
}

}  // namespace

TransferCurve TransferCurve::from_file_gamma(std::optional<double> file_gamma) {
  if (!file_gamma) return {};
  const auto g = static_cast<float>(*file_gamma);
  if (std::fabs(1.0 - 1.0f / g) <= 0.01) return {Kind::neutral, 1.0f};
  return {Kind::power, g};
}

float TransferCurve::encode(float x) const {
  switch (kind) {
    case Kind::srgb: return x <= 0.0031308f ? x * 12.92f : 1.055f * std::pow(x, 1.0f / 2.4f) - 0.055f;
    case Kind::power: return std::pow(std::max(x, 0.0f), 1.0f / gamma);
    case Kind::neutral: break;
  }
  return x;
}

float TransferCurve::decode(float x) const {
  switch (kind) {
    case Kind::srgb: return x < 0.04045f ? x / 12.92f : std::pow((x + 0.055f) / 1.055f, 2.4f);
    case Kind::power: return std::pow(std::max(x, 0.0f), 1.0f / (1.0f / gamma));  // as POV-Ray: via 1/gamma
    case Kind::neutral: break;
  }
  return x;
}

float TransferCurve::approximate_decoding_gamma() const {
  return kind == Kind::neutral ? 1.0f : kind == Kind::srgb ? 2.2f : gamma;
}

std::vector<std::uint16_t> encode_samples(const Image& image, const SampleLayout& layout) {
  const TransferCurve curve =
      image.encoding == Encoding::linear ? layout.curve : TransferCurve{TransferCurve::Kind::neutral, 1.0f};
  const int colours = layout.grey ? 1 : 3;
  const auto max = static_cast<float>(layout.max_value);
  Ditherer ditherer(layout.dither, image.width);
  std::vector<std::uint16_t> samples;
  samples.reserve(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4);
  for (int row = 0; row < image.height; ++row) {
    const int y = layout.bottom_up ? image.height - 1 - row : row;
    for (int x = 0; x < image.width; ++x) {
      const PixelValues v = pixel_values(image, image.pixel(x, y), layout);
      ChannelOffsets linear{}, quantum{};
      ditherer.offsets(x, y, linear, quantum);
      for (int c = 0; c < colours; ++c) {
        const auto i = static_cast<std::size_t>(c);
        const float value = v.c[c] + linear[i];
        const unsigned code = quantise(curve.encode(value) + quantum[i] / max, layout.max_value);
        linear[i] = clip01(value) - curve.decode(static_cast<float>(code) / max);
        samples.push_back(static_cast<std::uint16_t>(code));
      }
      if (layout.alpha) {
        const float value = v.alpha + linear[3];
        const unsigned code = quantise(value + quantum[3] / max, layout.max_value);
        linear[3] = clip01(value) - static_cast<float>(code) / max;
        samples.push_back(static_cast<std::uint16_t>(code));
      }
      ditherer.carry(x, linear);
    }
  }
  return samples;
}

std::vector<std::uint16_t> display_samples(const Image& image, int bits, bool with_alpha) {
  SampleLayout layout;
  layout.max_value = (1u << bits) - 1u;
  layout.alpha = with_alpha;
  return encode_samples(image, layout);
}

}  // namespace povtrace::image

// The integer samples POV-Ray 3.7 writes to integer image files (PNG, PPM, TGA, BMP, JPEG), shared by those
// writers (povray-pixel-pipeline.md §6; POV-Ray's source/base/image/encoding.cpp and colourspace.cpp).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Grey weights POV-Ray uses for greyscale output and for deciding whether to raise alpha for bright,
// transparent pixels.
inline constexpr float grey_weight_r = 0.297f;
inline constexpr float grey_weight_g = 0.589f;
inline constexpr float grey_weight_b = 0.114f;

// From linear light to file values: POV-Ray's encoding gamma (File_Gamma). Single precision, as POV-Ray.
struct TransferCurve {
  enum class Kind { srgb, power, neutral };
  Kind kind = Kind::srgb;
  float gamma = 2.2f;  // power: the decoding gamma, file value = linear^(1/gamma)

  // nullopt → sRGB; a power within 0.01 of 1 → neutral (as POV-Ray's PowerLawGammaCurve).
  static TransferCurve from_file_gamma(std::optional<double> file_gamma);
  float encode(float linear) const;
  float decode(float encoded) const;
  // The single power POV-Ray records in file headers (PNG gAMA, TGA extension): sRGB 2.2, neutral 1.
  float approximate_decoding_gamma() const;
};

struct SampleLayout {
  unsigned max_value = 255;  // samples are 0 … max_value
  bool alpha = false;        // a fourth (second, for grey) sample: alpha, colour un-premultiplied
  bool grey = false;         // one sample 0.297 R + 0.589 G + 0.114 B instead of R, G, B
  TransferCurve curve;
  Dither dither = Dither::none;
  bool bottom_up = false;    // rows visited and returned bottom row first (BMP)
};

// Samples for `image` in visiting order (rows top first unless bottom_up, x ascending), 1-4 per pixel.
// Per pixel of a linear image (POV-Ray's GetEncodedRGB(A)Value / GetEncodedGray(A)Value):
//   with alpha: α is raised to min(1, grey(colour)) when grey exceeds it, then colour is divided by α
//               (by 1e-6 where α = 0);
//   without:    the premultiplied colour is used as is (the image composited over black);
//   q = floor(clip(curve(value + dither linear offset) + dither quantum offset / max, 0, 1) · max + 0.5),
//   alpha without the curve. An `encoded` image skips the curve and the alpha raise.
std::vector<std::uint16_t> encode_samples(const Image& image, const SampleLayout& layout);

// encode_samples with sRGB, no dither, RGB(A), top row first, 2^bits − 1.
std::vector<std::uint16_t> display_samples(const Image& image, int bits, bool with_alpha);

}  // namespace povtrace::image

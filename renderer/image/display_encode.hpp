// The integer samples POV-Ray 3.7 writes to 8- and 16-bit files (PNG, PPM), shared by those writers
// (povray-pixel-pipeline.md §6).
#pragma once

#include <cstdint>
#include <vector>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Grey weights POV-Ray uses when deciding whether to raise alpha for bright, transparent pixels.
inline constexpr double grey_weight_r = 0.297;
inline constexpr double grey_weight_g = 0.589;
inline constexpr double grey_weight_b = 0.114;

// Samples for `image`, row-major, top row first, 3 (RGB) or 4 (RGBA, when `with_alpha`) per pixel, each in
// [0, 2^bits − 1]. Per pixel, for a linear image:
//   with_alpha: alpha α is raised to min(1, grey(colour)) when grey exceeds it, then colour is divided by α
//               (un-premultiplied; 0 where α = 0);
//   without:    the premultiplied colour is used as is (the image composited over black);
//   then value = srgb_encode(colour), clipped to [0,1] (NaN → 0), q = floor(value·(2^bits − 1) + 0.5).
// An `encoded` image skips srgb_encode and the alpha raise: its numbers already are display values.
std::vector<std::uint16_t> display_samples(const Image& image, int bits, bool with_alpha);

}  // namespace povtrace::image

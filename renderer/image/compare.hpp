// Comparing two renders: error statistics, a false-colour difference image and a side-by-side strip
// (the "compare" stage of STYLE.md (a), step 7).
//
// Comparison space: two images with the same Encoding are compared as stored (two PNGs by their display
// values, two EXRs in linear light). When one is linear and the other encoded, the encoded one is converted
// with to_linear first. The compared channels are R, G, B, plus A when either image has alpha.
#pragma once

#include <cstddef>
#include <vector>

#include "renderer/image/image.hpp"

namespace povtrace::image {

struct CompareReport {
  double rmse = 0.0;            // root of the mean squared difference over all compared channel values
  double psnr = 0.0;            // 20·log10(1 / rmse) in dB (peak 1.0); +inf when identical
  double mean_abs_error = 0.0;  // mean |difference| over all compared channel values
  double max_abs_error = 0.0;   // largest |difference| of any channel …
  int max_x = 0;                // … found first (row-major) at this pixel
  int max_y = 0;
  int max_channel = 0;          // 0 R, 1 G, 2 B, 3 A
  std::size_t pixels_over_threshold = 0;  // pixels whose largest channel |difference| > threshold
  std::size_t pixel_count = 0;
  double share_over_threshold = 0.0;      // pixels_over_threshold / pixel_count (a fraction, not %)
  double threshold = 0.0;
};

// The space compare_images works in for `a` and `b` (see above).
Encoding comparison_encoding(const Image& a, const Image& b);

// Statistics of b − a. A channel difference is 0 where both values are equal (also equal infinities) and +inf
// where exactly one is NaN or the values are opposite infinities. Throws ImageError when the sizes differ.
CompareReport compare_images(const Image& a, const Image& b, double threshold);

// A false-colour map of each pixel's largest channel |difference| d, ready for a PNG (Encoding::encoded, no
// alpha): black where d = 0; blue, brightening with d, while 0 < d ≤ threshold; above the threshold a ramp
// green → yellow → red on a log scale from threshold to 16·threshold, saturating red beyond. Throws ImageError
// when the sizes differ.
Image difference_heat_map(const Image& a, const Image& b, double threshold);

// The images left to right in one strip. All must have the same height; if their encodings differ, all are
// converted to linear. has_alpha if any has alpha. Throws ImageError for an empty list, a null entry or
// different heights.
Image side_by_side(const std::vector<const Image*>& images);

}  // namespace povtrace::image

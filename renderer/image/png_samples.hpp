// PNG files as stored, for the images a scene reads (image_map, bump_map): the samples before any expansion or
// gamma decoding, the palette and its tRNS alpha, and the gamma chunks — everything POV-Ray 3.7's PNG reader
// (source/base/image/png.cpp Read) bases its decoding on.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace povtrace::image {

struct PngSamples {
  int width = 0;
  int height = 0;
  int bit_depth = 0;     // 1, 2, 4, 8 or 16
  int colour_type = 0;   // PNG's: 0 grey, 2 RGB, 3 palette, 4 grey + alpha, 6 RGBA
  int channels = 0;      // samples per pixel: 1 (grey, palette index), 2, 3 or 4
  std::vector<std::uint16_t> samples;   // row-major, top row first; values 0 … 2^bit_depth − 1
  std::vector<std::array<std::uint8_t, 3>> palette;
  std::vector<std::uint8_t> palette_alpha;   // a palette image's tRNS values (possibly fewer than its entries)
  bool has_trns = false;                     // any tRNS chunk (palette, grey or RGB)
  bool srgb_chunk = false;
  std::optional<double> file_gamma;          // the gAMA chunk's value (e.g. 0.45455)

  std::uint16_t sample(int x, int y, int channel) const {
    return samples[(static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) *
                       static_cast<std::size_t>(channels) +
                   static_cast<std::size_t>(channel)];
  }
};

// Reads any PNG file as stored. Throws ImageError (no such file, not a PNG, damaged, larger than 2^26 pixels).
PngSamples read_png_samples(const std::filesystem::path& file);

}  // namespace povtrace::image

// Binary PPM (P6) as POV-Ray 3.7 writes it (povray-pixel-pipeline.md §6): sRGB-encoded like PNG, 8 bits
// (maxval 255) or 16 bits (maxval 65535, big-endian), no alpha.
#pragma once

#include <filesystem>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Error messages do not repeat the path: write_image and read_image add it.
// Writes `image` to `file` (created or truncated). PPM has no alpha, so the premultiplied colour is written,
// i.e. the image composited over black. Throws ImageError.
void write_ppm(const Image& image, const std::filesystem::path& file, int bits_per_channel);

// Reads a binary P6 file (any maxval 1…65535; '#' comments allowed in the header) as an `encoded` image with
// values sample / maxval. Throws ImageError.
Image read_ppm(const std::filesystem::path& file);

}  // namespace povtrace::image

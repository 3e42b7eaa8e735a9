// Binary PPM (P6) as POV-Ray 3.7 writes it (povray-pixel-pipeline.md §6; its source/base/image/ppm.cpp):
// sRGB- or File_Gamma-encoded like PNG, Bits_Per_Color 5-16 stored unscaled with maxval 2^bits − 1 (one byte per
// sample up to 8 bits, two big-endian above), no alpha; Grayscale_Output gives a PGM (P5) of linear grey values.
// POV-Ray's header comments (software, date) are not written.
#pragma once

#include <filesystem>
#include <string>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Error messages do not repeat the path: write_image and read_image add it.
// The whole file for `image` (options: bits_per_channel 5-16, grayscale, file_gamma, dither).
std::string encode_ppm(const Image& image, const EncodeOptions& options);

// Writes `image` to `file` (created or truncated). PPM has no alpha, so the premultiplied colour is written,
// i.e. the image composited over black. Throws ImageError.
void write_ppm(const Image& image, const std::filesystem::path& file, int bits_per_channel);

// Reads a binary P6 (or greyscale P5) file (any maxval 1…65535; '#' comments allowed in the header) as an `encoded` image with
// values sample / maxval. Throws ImageError.
Image read_ppm(const std::filesystem::path& file);

}  // namespace povtrace::image

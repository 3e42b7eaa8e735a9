// PNG files as POV-Ray 3.7 writes them (povray-pixel-pipeline.md §6; its source/base/image/png.cpp): sRGB- or
// File_Gamma-encoded, Bits_Per_Color 5-16 (in 8- or 16-bit samples by left bit replication, with sBIT), RGB or
// RGBA with straight (un-premultiplied) alpha, or 16-bit grey (Grayscale_Output), gAMA (0.45455 for sRGB), sRGB
// (only for the sRGB curve) and oFFs 0,0 chunks. POV-Ray's tIME and tEXt (date, software) are not written.
#pragma once

#include <filesystem>
#include <string>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Error messages do not repeat the path: write_image and read_image add it.
// The whole file for `image` (options: bits_per_channel 5-16, grayscale, file_gamma, dither). Throws ImageError.
std::string encode_png(const Image& image, const EncodeOptions& options);

// Writes `image` to `file` (created or truncated; no temporary file, see write_image for that). A linear image
// is encoded as display_samples describes; an `encoded` one is quantised as is. Throws ImageError.
void write_png(const Image& image, const std::filesystem::path& file, int bits_per_channel);

// Reads any PNG (palette, grey, 1–16 bits, with or without alpha/tRNS) as an `encoded` image: values are the
// stored numbers divided by 2^bits − 1, colour premultiplied by alpha; has_alpha when the file carries alpha.
// Gamma chunks are ignored (every PNG is taken to be sRGB-encoded). Throws ImageError.
Image read_png(const std::filesystem::path& file);

}  // namespace povtrace::image

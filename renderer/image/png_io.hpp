// PNG files as POV-Ray 3.7 writes them (povray-pixel-pipeline.md §6): sRGB-encoded, 8 or 16 bits, RGB or RGBA
// with straight (un-premultiplied) alpha, gAMA 0.45455 and sRGB chunks.
#pragma once

#include <filesystem>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Error messages do not repeat the path: write_image and read_image add it.
// Writes `image` to `file` (created or truncated; no temporary file, see write_image for that). A linear image
// is encoded as display_samples describes; an `encoded` one is quantised as is. Throws ImageError.
void write_png(const Image& image, const std::filesystem::path& file, int bits_per_channel);

// Reads any PNG (palette, grey, 1–16 bits, with or without alpha/tRNS) as an `encoded` image: values are the
// stored numbers divided by 2^bits − 1, colour premultiplied by alpha; has_alpha when the file carries alpha.
// Gamma chunks are ignored (every PNG is taken to be sRGB-encoded). Throws ImageError.
Image read_png(const std::filesystem::path& file);

}  // namespace povtrace::image

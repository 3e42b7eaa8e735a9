// Targa files as POV-Ray 3.7 writes them (+FT uncompressed, +FC run-length encoded; its
// source/base/image/targa.cpp): an 18-byte header (type 2 or 10, top-left origin), BGR or, with alpha, BGRA
// pixels with straight (un-premultiplied) alpha, sRGB- or File_Gamma-encoded, then a TGA 2.0 extension area
// (software, date, gamma, alpha type) and footer. POV-Ray's platform and compiler comments are not written.
#pragma once

#include <string>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// The whole file for `image` (options: file_gamma, dither; alpha when image.has_alpha). Throws ImageError.
std::string encode_tga(const Image& image, const EncodeOptions& options, bool run_length);

// An uncompressed or run-length encoded true-colour (24/32-bit) or greyscale (8-bit) Targa file, as an
// `encoded` image (colour premultiplied; has_alpha for 32-bit pixels). Throws ImageError.
Image decode_tga(const std::string& bytes);

}  // namespace povtrace::image

// Windows BMP files as POV-Ray 3.7 writes them (+FB; its source/base/image/bmp.cpp): a 14-byte file header and
// a 40-byte BITMAPINFOHEADER (BI_RGB, resolution 0), rows bottom first, 24-bit BGR rows padded to 4 bytes or,
// with alpha (+UA), 32-bit BGRA with straight (un-premultiplied) alpha; sRGB- or File_Gamma-encoded.
#pragma once

#include <string>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// The whole file for `image` (options: file_gamma, dither; alpha when image.has_alpha). Throws ImageError.
std::string encode_bmp(const Image& image, const EncodeOptions& options);

// An uncompressed (BI_RGB) 24- or 32-bit BMP as an `encoded` image. A 32-bit file's fourth byte is read as
// alpha (POV-Ray's) unless it is 0 everywhere (the usual unused byte). Throws ImageError.
Image decode_bmp(const std::string& bytes);

}  // namespace povtrace::image

// JPEG files as POV-Ray 3.7 writes them (+FJ; its source/base/image/jpeg.cpp), through libjpeg: 8-bit RGB
// (the image composited over black; no alpha, no dithering), sRGB- or File_Gamma-encoded, stored as YCbCr
// without chroma subsampling, quality from Compression (0 and 1 mean 85), a COM marker naming the software.
#pragma once

#include <string>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// POV-Ray's quality for a Compression value: clipped to 0-100, with 0 (unset) and 1 meaning 85.
int jpeg_quality_for(int compression);

// The whole file for `image` (options: jpeg_quality as given to jpeg_quality_for, file_gamma). Throws ImageError.
std::string encode_jpeg(const Image& image, const EncodeOptions& options);

// Any baseline or progressive JPEG libjpeg reads, as an `encoded` RGB image. Throws ImageError.
Image decode_jpeg(const std::string& bytes);

}  // namespace povtrace::image

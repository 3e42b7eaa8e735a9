// Radiance RGBE (.hdr) files as POV-Ray 3.7 writes them (+FH; its source/base/image/hdr.cpp): linear colour
// (premultiplied, i.e. composited over black; no alpha), a text header (#?RADIANCE, SOFTWARE, CREATION_TIME,
// FORMAT=32-bit_rle_rgbe), "-Y h +X w", then scanlines run-length encoded per component when 8 to 32767
// pixels wide, flat otherwise.
#pragma once

#include <string>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// The whole file for `image` (linear; an `encoded` image is linearised first). options.dither applies as
// POV-Ray applies it to RGBE. Throws ImageError.
std::string encode_hdr(const Image& image, const EncodeOptions& options);

// A Radiance file (32-bit_rle_rgbe, -Y h +X w, new-style RLE or flat scanlines) as a linear image: component
// (m + 0.5) · 2^(e − 136), 0 where e = 0. Throws ImageError.
Image decode_hdr(const std::string& bytes);

}  // namespace povtrace::image

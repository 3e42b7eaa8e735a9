// OpenEXR files as POV-Ray 3.7 writes them (povray-pixel-pipeline.md §6): linear, premultiplied, not clipped,
// half float (32-bit float on request), channels R,G,B plus A only when the image has alpha, zip compression.
#pragma once

#include <filesystem>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Error messages do not repeat the path: write_image and read_image add it.
// Writes the linear `image` to `file` (created or truncated). Half floats round to nearest; values beyond
// ±65504 become ±inf. Throws ImageError.
void write_exr(const Image& image, const std::filesystem::path& file, bool full_float);

// Reads a scan-line or tiled EXR with R,G,B (or luminance-only Y) and optional A channels, any pixel type,
// as a linear image over its data window. has_alpha when the file has an A channel. Throws ImageError.
Image read_exr(const std::filesystem::path& file);

}  // namespace povtrace::image

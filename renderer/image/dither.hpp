// Dithering for integer image files, as POV-Ray 3.7 does it (Dither / Dither_Method; source/base/image/encoding.cpp):
// before a pixel is quantised it gets a `linear` offset, added to its linear value (error diffusion), and a
// `quantum` offset, added after the transfer curve in units of one code step (ordered dithering). After
// quantising, the writer hands the pixel's error (linear value minus the decoded code) back with carry().
#pragma once

#include <array>
#include <vector>

#include "renderer/image/image.hpp"

namespace povtrace::image {

// Single precision, as POV-Ray computes them, so that dithered files match POV-Ray's.
using ChannelOffsets = std::array<float, 4>;  // red (or grey), green, blue, alpha

class Ditherer {
 public:
  Ditherer(Dither method, int width);

  // The offsets for pixel (x, y). Writers visit pixels row by row, x ascending, each pixel once.
  void offsets(int x, int y, ChannelOffsets& linear, ChannelOffsets& quantum);

  // The quantisation error of the pixel just visited at column x, spread to pixels not yet visited.
  void carry(int x, const ChannelOffsets& error);

 private:
  Dither method_;
  std::size_t width_;
  ChannelOffsets last_{};                          // D1: the error of the pixel to the left
  std::vector<ChannelOffsets> this_row_, next_row_;  // D2 and FS
};

}  // namespace povtrace::image

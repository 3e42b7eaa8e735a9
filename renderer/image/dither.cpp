#include "renderer/image/dither.hpp"

#include <utility>

namespace povtrace::image {
namespace {

// Bayer matrices as POV-Ray 3.7 uses them: entry = rank / n² − 0.5, looked up as [x mod n][y mod n].
constexpr int bayer2[2][2] = {{1, 3}, {4, 2}};
constexpr int bayer3[3][3] = {{3, 7, 4}, {6, 1, 9}, {2, 8, 5}};
constexpr int bayer4[4][4] = {{1, 9, 3, 11}, {13, 5, 15, 7}, {4, 12, 2, 10}, {16, 8, 14, 6}};

float bayer_offset(Dither method, int x, int y) {
  const auto entry = [](int rank, double cells) { return static_cast<float>(rank / cells - 0.5); };
  switch (method) {
    case Dither::bayer2: return entry(bayer2[x % 2][y % 2], 4.0);
    case Dither::bayer3: return entry(bayer3[x % 3][y % 3], 9.0);
    default: return entry(bayer4[x % 4][y % 4], 16.0);
  }
}

void add_scaled(ChannelOffsets& target, const ChannelOffsets& error, float weight) {
  for (std::size_t c = 0; c < 4; ++c) target[c] += error[c] * weight;
}

}  // namespace

Ditherer::Ditherer(Dither method, int width) : method_(method), width_(static_cast<std::size_t>(width)) {
  // D2 keeps one spare entry to the right, FS one on each side (index = x + 1).
  const std::size_t size = method == Dither::diffusion2d ? width_ + 1 : width_ + 2;
  if (method == Dither::diffusion2d || method == Dither::floyd_steinberg) {
    this_row_.assign(size, ChannelOffsets{});
    next_row_.assign(size, ChannelOffsets{});
  }
}

void Ditherer::offsets(int x, int y, ChannelOffsets& linear, ChannelOffsets& quantum) {
  linear = {};
  quantum = {};
  const auto ux = static_cast<std::size_t>(x);
  switch (method_) {
    case Dither::none: return;
    case Dither::bayer2:
    case Dither::bayer3:
    case Dither::bayer4: quantum.fill(bayer_offset(method_, x, y)); return;
    case Dither::diffusion1d: linear = std::exchange(last_, ChannelOffsets{}); return;
    // As in POV-Ray, the row buffers are swapped only in carry() at x = 0, i.e. after column 0 has read its
    // offset: column 0 reads the previous row's buffer, not the errors carried down to it.
    case Dither::diffusion2d: linear = this_row_[ux]; return;
    case Dither::floyd_steinberg: linear = this_row_[ux + 1]; return;
  }
}

void Ditherer::carry(int x, const ChannelOffsets& error) {
  const auto ux = static_cast<std::size_t>(x);
  if (method_ == Dither::diffusion1d) {
    last_ = error;
    return;
  }
  if (method_ != Dither::diffusion2d && method_ != Dither::floyd_steinberg) return;
  if (x == 0) {
    std::swap(this_row_, next_row_);
    next_row_.assign(next_row_.size(), ChannelOffsets{});
  }
  if (method_ == Dither::diffusion2d) {
    add_scaled(this_row_[ux + 1], error, 2 / 4.0f);  // right
    add_scaled(next_row_[ux], error, 1 / 4.0f);      // below
    add_scaled(next_row_[ux + 1], error, 1 / 4.0f);  // below right
  } else {
    add_scaled(this_row_[ux + 2], error, 7 / 16.0f);  // right
    add_scaled(next_row_[ux], error, 3 / 16.0f);      // below left
    add_scaled(next_row_[ux + 1], error, 5 / 16.0f);  // below
    add_scaled(next_row_[ux + 2], error, 1 / 16.0f);  // below right
  }
}

}  // namespace povtrace::image

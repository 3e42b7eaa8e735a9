// PNG encoding as POV-Ray 3.7 does it (povray-pixel-pipeline.md §6): sRGB curve, clip, q = floor(v·max + 0.5),
// gAMA + sRGB chunks, straight alpha raised for bright transparent pixels.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/image/image.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::image {
namespace {

using test::ScratchFolder;
using Samples = std::vector<int>;

Image row_of(const std::vector<std::array<float, 4>>& pixels, bool has_alpha) {
  Image image(static_cast<int>(pixels.size()), 1);
  image.has_alpha = has_alpha;
  for (std::size_t x = 0; x < pixels.size(); ++x) std::copy(pixels[x].begin(), pixels[x].end(), image.pixel(int(x), 0));
  return image;
}

Image write_png_and_read(const Image& image, const ScratchFolder& folder, int bits = 8) {
  EncodeOptions options;
  options.format = FileFormat::png;
  options.bits_per_channel = bits;
  write_image(image, folder / "out.png", options);
  return read_image(folder / "out.png");
}

// The integers stored in the file for pixel (x, 0): read_image premultiplies, so undo that first.
Samples stored_samples(const Image& read, int x, int bits) {
  const double max_code = std::ldexp(1.0, bits) - 1.0;
  const float* p = read.pixel(x, 0);
  const double alpha = read.has_alpha ? p[3] : 1.0;
  Samples samples;
  for (int c = 0; c < 3; ++c) samples.push_back(int(std::lround((alpha > 0 ? p[c] / alpha : 0.0) * max_code)));
  if (read.has_alpha) samples.push_back(int(std::lround(alpha * max_code)));
  return samples;
}

// PNG chunk types in file order, from the raw bytes (length, type, data, CRC after the 8-byte signature).
std::vector<std::string> chunk_types(const std::string& bytes, std::string* gama_data = nullptr) {
  std::vector<std::string> types;
  for (std::size_t pos = 8; pos + 8 <= bytes.size();) {
    const auto byte = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(bytes[i])); };
    const std::uint32_t length = byte(pos) << 24 | byte(pos + 1) << 16 | byte(pos + 2) << 8 | byte(pos + 3);
    types.push_back(bytes.substr(pos + 4, 4));
    if (gama_data && types.back() == "gAMA") *gama_data = bytes.substr(pos + 8, length);
    pos += 12 + length;
  }
  return types;
}

TEST(PngIo, PipelineExampleValues8Bit) {
  // [V item6_gamma_output] linear 0.05 → 63, 0.5 → 188, <2,1,0.25> → (255,255,137).
  ScratchFolder folder;
  const Image read = write_png_and_read(
      row_of({{0.05f, 0.05f, 0.05f, 1.0f}, {0.5f, 0.5f, 0.5f, 1.0f}, {2.0f, 1.0f, 0.25f, 1.0f}}, false), folder);
  EXPECT_EQ(read.encoding, Encoding::encoded);
  EXPECT_FALSE(read.has_alpha);
  EXPECT_EQ(stored_samples(read, 0, 8), (Samples{63, 63, 63}));
  EXPECT_EQ(stored_samples(read, 1, 8), (Samples{188, 188, 188}));
  EXPECT_EQ(stored_samples(read, 2, 8), (Samples{255, 255, 137}));
}

TEST(PngIo, PipelineExampleValues16Bit) {
  // POV-Ray 3.7 +FN16 (and +FP16) writes these for the same three colours.
  ScratchFolder folder;
  const Image read = write_png_and_read(
      row_of({{0.05f, 0.05f, 0.05f, 1.0f}, {0.5f, 0.5f, 0.5f, 1.0f}, {2.0f, 1.0f, 0.25f, 1.0f}}, false), folder, 16);
  EXPECT_EQ(stored_samples(read, 0, 16), (Samples{16240, 16240, 16240}));
  EXPECT_EQ(stored_samples(read, 1, 16), (Samples{48192, 48192, 48192}));
  EXPECT_EQ(stored_samples(read, 2, 16), (Samples{65535, 65535, 35199}));
}

TEST(PngIo, Srgb16BitRoundTrip) {
  ScratchFolder folder;
  constexpr int count = 1001;
  Image image(count, 1);
  for (int x = 0; x < count; ++x) std::fill_n(image.pixel(x, 0), 3, float(x) / (count - 1));
  const Image read = write_png_and_read(image, folder, 16);
  const Image linear = to_linear(read);
  // Quantising to 16 bits moves the encoded value by at most half a code. Decoding stretches that by the
  // curve's slope, at most 2.4/1.055 (at 1.0), so linear values are within 1.14/65535.
  constexpr double half_code = 0.5 / 65535.0;
  constexpr double max_decode_slope = 2.4 / 1.055;
  for (int x = 0; x < count; ++x) {
    const double v = image.pixel(x, 0)[0];
    EXPECT_NEAR(read.pixel(x, 0)[1], srgb_encode(v), half_code + 1e-7) << v;
    EXPECT_NEAR(linear.pixel(x, 0)[1], v, half_code * max_decode_slope + 1e-7) << v;
  }
}

TEST(PngIo, WritesGamaAndSrgbChunks) {
  ScratchFolder folder;
  write_png_and_read(row_of({{0.5f, 0.5f, 0.5f, 1.0f}}, false), folder);
  std::string gama;
  const std::vector<std::string> types = chunk_types(test::read_bytes(folder / "out.png"), &gama);
  ASSERT_FALSE(types.empty());
  EXPECT_EQ(types.front(), "IHDR");
  EXPECT_NE(std::find(types.begin(), types.end(), "sRGB"), types.end());
  ASSERT_NE(std::find(types.begin(), types.end(), "gAMA"), types.end());
  EXPECT_EQ(gama, std::string("\x00\x00\xb1\x8f", 4));  // 45455 = 0.45455 × 100000
}

TEST(PngIo, AlphaIsWrittenStraight) {
  // [V item5_background_alpha] +UA PNG: premultiplied (0.4,0.2,0.1) α .4 → (255,188,137,102).
  ScratchFolder folder;
  const Image read = write_png_and_read(row_of({{0.4f, 0.2f, 0.1f, 0.4f}}, true), folder);
  EXPECT_TRUE(read.has_alpha);
  EXPECT_EQ(stored_samples(read, 0, 8), (Samples{255, 188, 137, 102}));
}

TEST(PngIo, AlphaIsRaisedForBrightTransparentPixels) {
  // POV-Ray 3.7 +UA +FN output for these premultiplied linear colours (the half floats of its own EXR of the
  // same scene): where grey(colour) > α, α becomes min(1, grey) before un-premultiplying.
  ScratchFolder folder;
  const Image read = write_png_and_read(row_of({{0.759765625f, 0.759765625f, 0.759765625f, 0.189941406f},
                                                {1.080078125f, 0.360107422f, 0.072021484f, 0.360107422f},
                                                {0.300048828f, 0.150024414f, 0.075012207f, 0.75f},
                                                {0.765136719f, 0.0102005f, 0.254882812f, 0.509765625f}},
                                               true),
                                        folder);
  EXPECT_EQ(stored_samples(read, 0, 8), (Samples{255, 255, 255, 194}));
  EXPECT_EQ(stored_samples(read, 1, 8), (Samples{255, 213, 102, 138}));
  EXPECT_EQ(stored_samples(read, 2, 8), (Samples{170, 124, 89, 191}));
  EXPECT_EQ(stored_samples(read, 3, 8), (Samples{255, 39, 188, 130}));
}

TEST(PngIo, FullyTransparentPixelIsZero) {
  ScratchFolder folder;
  const Image read = write_png_and_read(row_of({{0.0f, 0.0f, 0.0f, 0.0f}}, true), folder);
  EXPECT_EQ(stored_samples(read, 0, 8), (Samples{0, 0, 0, 0}));
}

TEST(PngIo, NegativeAndNanClipToZero) {
  ScratchFolder folder;
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const Image read = write_png_and_read(row_of({{-0.5f, nan, 1e30f, 1.0f}}, false), folder);
  EXPECT_EQ(stored_samples(read, 0, 8), (Samples{0, 0, 255}));
}

TEST(PngIo, EncodedImageIsWrittenAsIs) {
  ScratchFolder folder;
  Image image = row_of({{0.5f, 0.25f, 1.0f, 1.0f}}, false);
  image.encoding = Encoding::encoded;
  const Image read = write_png_and_read(image, folder);
  EXPECT_EQ(stored_samples(read, 0, 8), (Samples{128, 64, 255}));  // floor(0.5·255 + 0.5) = 128
}

TEST(PngIo, RejectsBitDepthsOutsidePovRaysRange) {
  ScratchFolder folder;
  EncodeOptions options;
  options.format = FileFormat::png;
  for (const int bits : {4, 17}) {
    options.bits_per_channel = bits;
    EXPECT_THROW(write_image(Image(1, 1), folder / "out.png", options), ImageError);
  }
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace povtrace::image

// Binary PPM (P6): sRGB-encoded like PNG, 8-bit (maxval 255) or 16-bit big-endian (maxval 65535), no alpha.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "renderer/image/image.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::image {
namespace {

using test::ScratchFolder;
using namespace std::string_literals;

Image pipeline_example() {
  Image image(3, 1);
  const float colours[3][3] = {{0.05f, 0.05f, 0.05f}, {0.5f, 0.5f, 0.5f}, {2.0f, 1.0f, 0.25f}};
  for (int x = 0; x < 3; ++x) std::copy(colours[x], colours[x] + 3, image.pixel(x, 0));
  return image;
}

std::string write_ppm_bytes(const Image& image, const ScratchFolder& folder, int bits) {
  EncodeOptions options;
  options.format = FileFormat::ppm;
  options.bits_per_channel = bits;
  write_image(image, folder / "out.ppm", options);
  return test::read_bytes(folder / "out.ppm");
}

TEST(PpmIo, EightBitHeaderAndBytes) {
  ScratchFolder folder;
  const std::string expected = std::string("P6\n3 1\n255\n") + "\x3f\x3f\x3f" + "\xbc\xbc\xbc" + "\xff\xff\x89";
  EXPECT_EQ(write_ppm_bytes(pipeline_example(), folder, 8), expected);  // 63, 188, (255,255,137)
}

TEST(PpmIo, SixteenBitIsBigEndian) {
  ScratchFolder folder;
  // 16240 = 0x3f70, 48192 = 0xbc40, 65535, 35199 = 0x897f: POV-Ray 3.7 +FP16 output for these colours.
  const std::string expected = std::string("P6\n3 1\n65535\n") + "\x3f\x70\x3f\x70\x3f\x70" +
                               "\xbc\x40\xbc\x40\xbc\x40" + "\xff\xff\xff\xff\x89\x7f";
  EXPECT_EQ(write_ppm_bytes(pipeline_example(), folder, 16), expected);
}

TEST(PpmIo, AlphaImageIsCompositedOverBlack) {
  ScratchFolder folder;
  Image image(1, 1);
  image.has_alpha = true;
  image.rgba = {0.4f, 0.2f, 0.1f, 0.4f};
  const std::string bytes = write_ppm_bytes(image, folder, 8);
  const std::string header = "P6\n1 1\n255\n";
  ASSERT_EQ(bytes.size(), header.size() + 3);
  EXPECT_EQ(bytes.substr(0, header.size()), header);
  for (int c = 0; c < 3; ++c) {
    const int expected = int(std::floor(srgb_encode(image.rgba[c]) * 255.0 + 0.5));
    EXPECT_EQ(static_cast<unsigned char>(bytes[header.size() + c]), expected);
  }
}

TEST(PpmIo, ReadsP6WithComments) {
  ScratchFolder folder;
  test::write_bytes(folder / "in.ppm", std::string("P6\n# made by hand\n2 1 # size\n1000\n") +
                                           "\x00\x00\x01\xf4\x03\xe8"s + "\x00\x01\x00\x02\x00\x03"s);
  const Image image = read_image(folder / "in.ppm");
  EXPECT_EQ(image.encoding, Encoding::encoded);
  EXPECT_FALSE(image.has_alpha);
  ASSERT_EQ(image.width, 2);
  ASSERT_EQ(image.height, 1);
  EXPECT_FLOAT_EQ(image.pixel(0, 0)[0], 0.0f);
  EXPECT_FLOAT_EQ(image.pixel(0, 0)[1], 0.5f);
  EXPECT_FLOAT_EQ(image.pixel(0, 0)[2], 1.0f);
  EXPECT_FLOAT_EQ(image.pixel(1, 0)[2], 0.003f);
}

TEST(PpmIo, RoundTrip8Bit) {
  ScratchFolder folder;
  write_ppm_bytes(pipeline_example(), folder, 8);
  const Image image = read_image(folder / "out.ppm");
  EXPECT_FLOAT_EQ(image.pixel(1, 0)[0], 188.0f / 255.0f);
  EXPECT_FLOAT_EQ(image.pixel(2, 0)[2], 137.0f / 255.0f);
}

TEST(PpmIo, TruncatedFileThrows) {
  ScratchFolder folder;
  test::write_bytes(folder / "in.ppm", std::string("P6\n2 2\n255\n") + "\x01\x02\x03");
  EXPECT_THROW(read_image(folder / "in.ppm"), ImageError);
}

}  // namespace
}  // namespace povtrace::image

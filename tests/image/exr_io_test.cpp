// EXR files: POV-Ray writes half floats, linear, unclipped, RGB or RGBA (povray-pixel-pipeline.md §6).
#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/image/image.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::image {
namespace {

using test::ScratchFolder;

// Half floats keep 11 significant bits: rounding to nearest is within 2^-11 of the value, relatively.
constexpr double half_relative_precision = 1.0 / 2048.0;

Image ramp_image(bool has_alpha) {
  Image image(4, 3);
  image.has_alpha = has_alpha;
  const float values[] = {0.05f, 0.5f, 2.0f, 0.25f, 1e-3f, 3.7f, 1000.25f, -0.5f, 0.123456f, 65504.0f, 7.5f, 0.0f};
  for (std::size_t p = 0; p < image.rgba.size() / 4; ++p) {
    for (std::size_t c = 0; c < 3; ++c) image.rgba[p * 4 + c] = values[(p * 3 + c) % 12];
    image.rgba[p * 4 + 3] = has_alpha ? 0.25f + 0.05f * float(p) : 1.0f;
  }
  return image;
}

Image write_and_read(const Image& image, const ScratchFolder& folder, bool full_float) {
  EncodeOptions options;
  options.format = FileFormat::exr;
  options.exr_full_float = full_float;
  write_image(image, folder / "out.exr", options);
  return read_image(folder / "out.exr");
}

TEST(ExrIo, HalfRoundTripIsWithinHalfPrecision) {
  ScratchFolder folder;
  const Image original = ramp_image(false);
  const Image read = write_and_read(original, folder, false);
  ASSERT_EQ(read.width, 4);
  ASSERT_EQ(read.height, 3);
  EXPECT_EQ(read.encoding, Encoding::linear);
  for (std::size_t i = 0; i < original.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    EXPECT_NEAR(read.rgba[i], original.rgba[i], std::fabs(original.rgba[i]) * half_relative_precision) << i;
  }
}

TEST(ExrIo, ValuesAboveOneSurviveUnclipped) {
  ScratchFolder folder;
  Image image(2, 1);
  image.pixel(0, 0)[0] = 2.0f;
  image.pixel(0, 0)[1] = 100.0f;
  image.pixel(0, 0)[2] = 0.25f;
  image.pixel(1, 0)[0] = 1e5f;    // beyond half's largest finite value 65504
  image.pixel(1, 0)[1] = -3.0f;
  const Image read = write_and_read(image, folder, false);
  EXPECT_EQ(read.pixel(0, 0)[0], 2.0f);
  EXPECT_EQ(read.pixel(0, 0)[1], 100.0f);
  EXPECT_EQ(read.pixel(0, 0)[2], 0.25f);
  EXPECT_EQ(read.pixel(1, 0)[0], std::numeric_limits<float>::infinity());
  EXPECT_EQ(read.pixel(1, 0)[1], -3.0f);
}

TEST(ExrIo, PipelineExampleValuesAsPovRayWritesThem) {
  // [V item6_gamma_output] assumed_gamma 1 → EXR 0.05, 0.5, (2,1,0.25); half rounds 0.05 to 0.049987793.
  ScratchFolder folder;
  Image image(3, 1);
  const float colours[3][3] = {{0.05f, 0.05f, 0.05f}, {0.5f, 0.5f, 0.5f}, {2.0f, 1.0f, 0.25f}};
  for (int x = 0; x < 3; ++x) std::copy(colours[x], colours[x] + 3, image.pixel(x, 0));
  const Image read = write_and_read(image, folder, false);
  EXPECT_FLOAT_EQ(read.pixel(0, 0)[0], 0.049987793f);
  EXPECT_EQ(read.pixel(1, 0)[1], 0.5f);
  EXPECT_EQ(read.pixel(2, 0)[0], 2.0f);
  EXPECT_EQ(read.pixel(2, 0)[2], 0.25f);
}

TEST(ExrIo, AlphaChannelOnlyWithHasAlpha) {
  ScratchFolder folder;
  Image opaque = ramp_image(false);
  opaque.rgba[3] = 0.5f;  // ignored: without has_alpha no A channel is written
  const Image read_opaque = write_and_read(opaque, folder, false);
  EXPECT_FALSE(read_opaque.has_alpha);
  EXPECT_EQ(read_opaque.rgba[3], 1.0f);  // a missing A channel reads as 1

  const Image transparent = ramp_image(true);
  const Image read_transparent = write_and_read(transparent, folder, false);
  EXPECT_TRUE(read_transparent.has_alpha);
  for (std::size_t i = 3; i < transparent.rgba.size(); i += 4) {
    EXPECT_NEAR(read_transparent.rgba[i], transparent.rgba[i], transparent.rgba[i] * half_relative_precision);
  }
}

TEST(ExrIo, FullFloatIsExact) {
  ScratchFolder folder;
  Image image = ramp_image(true);
  image.rgba[0] = 0.1f;
  image.rgba[1] = 1e-30f;
  image.rgba[2] = 3.0e10f;
  const Image read = write_and_read(image, folder, true);
  EXPECT_TRUE(read.has_alpha);
  EXPECT_EQ(read.rgba, image.rgba);
}

TEST(ExrIo, EncodedImageIsLinearisedForExr) {
  ScratchFolder folder;
  Image image(1, 1);
  image.encoding = Encoding::encoded;
  image.rgba = {0.5f, 0.0f, 1.0f, 1.0f};
  const Image read = write_and_read(image, folder, true);
  EXPECT_EQ(read.encoding, Encoding::linear);
  EXPECT_FLOAT_EQ(read.rgba[0], static_cast<float>(srgb_decode(0.5)));
  EXPECT_EQ(read.rgba[1], 0.0f);
  EXPECT_FLOAT_EQ(read.rgba[2], 1.0f);
}

}  // namespace
}  // namespace povtrace::image

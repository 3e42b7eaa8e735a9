// compare_images, difference_heat_map and side_by_side.
#include <cmath>
#include <limits>
#include <vector>

#include <gtest/gtest.h>

#include "renderer/image/compare.hpp"
#include "renderer/image/image.hpp"

namespace povtrace::image {
namespace {

constexpr double threshold = 1.0 / 255.0;

Image grey_image(int w, int h, float value) {
  Image image(w, h);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) {
    if (i % 4 != 3) image.rgba[i] = value;
  }
  return image;
}

TEST(CompareImages, IdenticalImages) {
  const Image a = grey_image(3, 2, 0.5f);
  const CompareReport report = compare_images(a, a, threshold);
  EXPECT_EQ(report.rmse, 0.0);
  EXPECT_EQ(report.psnr, std::numeric_limits<double>::infinity());
  EXPECT_EQ(report.mean_abs_error, 0.0);
  EXPECT_EQ(report.max_abs_error, 0.0);
  EXPECT_EQ(report.pixels_over_threshold, 0u);
  EXPECT_EQ(report.pixel_count, 6u);
  EXPECT_EQ(report.share_over_threshold, 0.0);
  EXPECT_EQ(report.threshold, threshold);
}

TEST(CompareImages, KnownDifference) {
  // 2×2 RGB, 12 compared values. Pixel (1,0) R differs by 0.25 (over the threshold), pixel (0,1) G by 0.002
  // (under it). Sum of squares 0.0625 + 0.000004 = 0.062504; MSE = 0.062504/12 = 0.00520867;
  // RMSE = 0.0721711; PSNR = −10·log10(MSE) = 22.8329 dB; mean |d| = 0.252/12 = 0.021; 1 of 4 pixels over.
  const Image a = grey_image(2, 2, 0.5f);
  Image b = a;
  b.pixel(1, 0)[0] = 0.75f;
  b.pixel(0, 1)[1] = 0.502f;
  const CompareReport report = compare_images(a, b, threshold);
  EXPECT_NEAR(report.rmse, 0.0721711, 1e-6);
  EXPECT_NEAR(report.psnr, 22.8329, 1e-3);
  EXPECT_NEAR(report.mean_abs_error, 0.021, 1e-7);
  EXPECT_DOUBLE_EQ(report.max_abs_error, 0.25);
  EXPECT_EQ(report.max_x, 1);
  EXPECT_EQ(report.max_y, 0);
  EXPECT_EQ(report.max_channel, 0);
  EXPECT_EQ(report.pixels_over_threshold, 1u);
  EXPECT_DOUBLE_EQ(report.share_over_threshold, 0.25);
}

TEST(CompareImages, ThresholdIsExclusive) {
  const Image a = grey_image(1, 1, 0.0f);
  const Image b = grey_image(1, 1, 0.5f);
  EXPECT_EQ(compare_images(a, b, 0.5).pixels_over_threshold, 0u);
  EXPECT_EQ(compare_images(a, b, 0.4999).pixels_over_threshold, 1u);
}

TEST(CompareImages, SizeMismatchThrows) {
  EXPECT_THROW(compare_images(grey_image(2, 2, 0.5f), grey_image(2, 3, 0.5f), threshold), ImageError);
  EXPECT_THROW(difference_heat_map(grey_image(2, 2, 0.5f), grey_image(3, 2, 0.5f), threshold), ImageError);
}

TEST(CompareImages, MixedEncodingsCompareInLinearLight) {
  Image encoded = grey_image(2, 1, 0.5f);
  encoded.encoding = Encoding::encoded;
  const Image linear = grey_image(2, 1, static_cast<float>(srgb_decode(0.5)));
  EXPECT_EQ(comparison_encoding(encoded, linear), Encoding::linear);
  EXPECT_NEAR(compare_images(encoded, linear, threshold).max_abs_error, 0.0, 1e-7);
  EXPECT_NEAR(compare_images(linear, encoded, threshold).max_abs_error, 0.0, 1e-7);
}

TEST(CompareImages, SameEncodingComparesAsStored) {
  Image a = grey_image(1, 1, 0.5f);
  Image b = grey_image(1, 1, 0.5f + 2.0f / 255.0f);
  a.encoding = b.encoding = Encoding::encoded;
  EXPECT_EQ(comparison_encoding(a, b), Encoding::encoded);
  EXPECT_NEAR(compare_images(a, b, threshold).max_abs_error, 2.0 / 255.0, 1e-7);
}

TEST(CompareImages, AlphaComparedOnlyWhenEitherHasIt) {
  Image a = grey_image(1, 1, 0.5f);
  Image b = a;
  b.rgba[3] = 0.25f;  // ignored: neither image has alpha
  EXPECT_EQ(compare_images(a, b, threshold).max_abs_error, 0.0);
  b.has_alpha = true;  // now compared against a's implicit alpha 1
  const CompareReport report = compare_images(a, b, threshold);
  EXPECT_DOUBLE_EQ(report.max_abs_error, 0.75);
  EXPECT_EQ(report.max_channel, 3);
  EXPECT_NEAR(report.mean_abs_error, 0.75 / 4.0, 1e-12);
}

TEST(CompareImages, InfinitiesAndNan) {
  const float inf = std::numeric_limits<float>::infinity();
  Image a = grey_image(2, 1, 0.5f);
  Image b = a;
  a.pixel(0, 0)[0] = b.pixel(0, 0)[0] = inf;  // equal infinities: no difference
  EXPECT_EQ(compare_images(a, b, threshold).max_abs_error, 0.0);
  b.pixel(1, 0)[2] = std::numeric_limits<float>::quiet_NaN();
  const CompareReport report = compare_images(a, b, threshold);
  EXPECT_EQ(report.max_abs_error, std::numeric_limits<double>::infinity());
  EXPECT_EQ(report.max_x, 1);
  EXPECT_EQ(report.max_channel, 2);
  EXPECT_EQ(report.pixels_over_threshold, 1u);
}

TEST(CompareImages, EmptyImages) {
  const CompareReport report = compare_images(Image(), Image(), threshold);
  EXPECT_EQ(report.pixel_count, 0u);
  EXPECT_EQ(report.share_over_threshold, 0.0);
  EXPECT_EQ(report.psnr, std::numeric_limits<double>::infinity());
}

TEST(DifferenceHeatMap, ColoursByLargestChannelDifference) {
  const Image a = grey_image(5, 1, 0.0f);
  Image b = a;
  b.pixel(1, 0)[1] = float(threshold / 2);    // under: blue
  b.pixel(2, 0)[2] = float(threshold * 1.01);  // just over: green
  b.pixel(3, 0)[0] = float(threshold * 4);     // halfway on the log ramp: yellow
  b.pixel(4, 0)[0] = float(threshold * 100);   // beyond 16×: red
  const Image map = difference_heat_map(a, b, threshold);
  EXPECT_EQ(map.encoding, Encoding::encoded);
  EXPECT_FALSE(map.has_alpha);
  const auto rgb = [&](int x) { return std::vector<float>(map.pixel(x, 0), map.pixel(x, 0) + 3); };
  EXPECT_EQ(rgb(0), (std::vector<float>{0, 0, 0}));
  EXPECT_EQ(rgb(1)[0], 0.0f);
  EXPECT_EQ(rgb(1)[1], 0.0f);
  EXPECT_GT(rgb(1)[2], 0.3f);
  EXPECT_LT(rgb(2)[0], 0.05f);
  EXPECT_EQ(rgb(2)[1], 1.0f);
  EXPECT_EQ(rgb(2)[2], 0.0f);
  EXPECT_NEAR(rgb(3)[0], 1.0f, 1e-5);
  EXPECT_NEAR(rgb(3)[1], 1.0f, 1e-5);
  EXPECT_EQ(rgb(4), (std::vector<float>{1, 0, 0}));
}

TEST(SideBySide, PlacesImagesLeftToRight) {
  const Image a = grey_image(2, 2, 0.25f);
  Image b = grey_image(3, 2, 0.75f);
  b.has_alpha = true;
  const Image strip = side_by_side({&a, &b});
  EXPECT_EQ(strip.width, 5);
  EXPECT_EQ(strip.height, 2);
  EXPECT_TRUE(strip.has_alpha);
  EXPECT_EQ(strip.pixel(1, 1)[0], 0.25f);
  EXPECT_EQ(strip.pixel(2, 1)[0], 0.75f);
  EXPECT_EQ(strip.pixel(4, 0)[2], 0.75f);
}

TEST(SideBySide, MixedEncodingsBecomeLinear) {
  Image a = grey_image(1, 1, 0.5f);
  a.encoding = Encoding::encoded;
  const Image b = grey_image(1, 1, 0.5f);
  const Image strip = side_by_side({&a, &b});
  EXPECT_EQ(strip.encoding, Encoding::linear);
  EXPECT_NEAR(strip.pixel(0, 0)[0], srgb_decode(0.5), 1e-6);
  EXPECT_EQ(strip.pixel(1, 0)[0], 0.5f);
}

TEST(SideBySide, RejectsBadInput) {
  const Image a = grey_image(2, 2, 0.5f);
  const Image b = grey_image(2, 3, 0.5f);
  EXPECT_THROW(side_by_side({}), ImageError);
  EXPECT_THROW(side_by_side({&a, nullptr}), ImageError);
  EXPECT_THROW(side_by_side({&a, &b}), ImageError);
}

}  // namespace
}  // namespace povtrace::image

// Format dispatch, the sRGB curve and linearisation.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "renderer/image/image.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::image {
namespace {

using test::ScratchFolder;

template <class Action>
std::string error_message(Action action) {
  try {
    action();
  } catch (const ImageError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no ImageError thrown";
  return "";
}

TEST(ImageIo, FormatFromExtension) {
  EXPECT_EQ(format_from_extension("a/b.png"), FileFormat::png);
  EXPECT_EQ(format_from_extension("B.PNG"), FileFormat::png);
  EXPECT_EQ(format_from_extension("x.Exr"), FileFormat::exr);
  EXPECT_EQ(format_from_extension("x.ppm"), FileFormat::ppm);
  EXPECT_EQ(format_from_extension("x.pgm"), FileFormat::ppm);
  EXPECT_EQ(format_from_extension("x.tga"), FileFormat::tga);  // POV-Ray's extension for +FT and +FC
  EXPECT_EQ(format_from_extension("x.BMP"), FileFormat::bmp);
  EXPECT_EQ(format_from_extension("x.hdr"), FileFormat::hdr);
  EXPECT_EQ(format_from_extension("x.jpg"), FileFormat::jpeg);
  EXPECT_EQ(format_from_extension("x.jpeg"), FileFormat::jpeg);
  EXPECT_EQ(format_from_extension("x.gif"), std::nullopt);
  EXPECT_EQ(format_from_extension("png"), std::nullopt);
  EXPECT_EQ(format_from_extension("x.png.bak"), std::nullopt);
}

TEST(ImageIo, SrgbCurveKnownValues) {
  EXPECT_DOUBLE_EQ(srgb_encode(0.0), 0.0);
  EXPECT_DOUBLE_EQ(srgb_encode(1.0), 1.0);
  EXPECT_DOUBLE_EQ(srgb_encode(0.001), 0.01292);               // the straight segment
  EXPECT_NEAR(srgb_encode(0.5), 0.735356983, 1e-9);
  EXPECT_NEAR(srgb_encode(0.0031308), 0.04045, 1e-6);           // both pieces meet here
  EXPECT_NEAR(srgb_decode(0.04045), 0.0031308, 1e-6);
  EXPECT_NEAR(srgb_encode(2.0), 1.055 * std::pow(2.0, 1 / 2.4) - 0.055, 1e-12);  // not clipped
}

TEST(ImageIo, SrgbDecodeInvertsEncode) {
  for (double v = 0.0; v <= 1.5; v += 0.001) EXPECT_NEAR(srgb_decode(srgb_encode(v)), v, 1e-12) << v;
}

TEST(ImageIo, ToLinearDecodesStraightColourAndKeepsAlpha) {
  Image image(2, 1);
  image.encoding = Encoding::encoded;
  image.has_alpha = true;
  const float e = static_cast<float>(srgb_encode(0.5));
  image.rgba = {e * 0.4f, 0.0f, 0.4f, 0.4f, 0.0f, 0.0f, 0.0f, 0.0f};  // premultiplied encoded values
  const Image linear = to_linear(image);
  EXPECT_EQ(linear.encoding, Encoding::linear);
  EXPECT_NEAR(linear.rgba[0], 0.5 * 0.4, 1e-6);
  EXPECT_NEAR(linear.rgba[2], 0.4, 1e-6);  // straight 1.0 stays 1.0
  EXPECT_EQ(linear.rgba[3], 0.4f);
  EXPECT_EQ(linear.rgba[4], 0.0f);
}

TEST(ImageIo, ToLinearLeavesLinearImagesAlone) {
  Image image(1, 1);
  image.rgba = {0.3f, 2.0f, -1.0f, 1.0f};
  EXPECT_EQ(to_linear(image).rgba, image.rgba);
}

TEST(ImageIo, ReadDispatchesOnContentNotName) {
  ScratchFolder folder;
  Image image(1, 1);
  image.rgba = {2.0f, 0.5f, 0.25f, 1.0f};
  EncodeOptions options;
  options.format = FileFormat::exr;
  write_image(image, folder / "really_an_exr.png", options);
  const Image read = read_image(folder / "really_an_exr.png");
  EXPECT_EQ(read.encoding, Encoding::linear);
  EXPECT_EQ(read.rgba[0], 2.0f);
}

TEST(ImageIo, MissingFileThrowsNamingIt) {
  ScratchFolder folder;
  const std::string message = error_message([&] { read_image(folder / "missing.exr"); });
  EXPECT_NE(message.find("missing.exr"), std::string::npos) << message;
}

TEST(ImageIo, GarbageThrowsNamingTheExpectedFormat) {
  ScratchFolder folder;
  test::write_bytes(folder / "bad.png", "this is not a picture");
  const std::string message = error_message([&] { read_image(folder / "bad.png"); });
  EXPECT_NE(message.find("bad.png"), std::string::npos) << message;
  EXPECT_NE(message.find("PNG"), std::string::npos) << message;
}

TEST(ImageIo, TruncatedPngAndExrThrow) {
  ScratchFolder folder;
  Image image(64, 64);
  for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = float(i % 97) / 97.0f;
  for (const FileFormat format : {FileFormat::png, FileFormat::exr}) {
    EncodeOptions options;
    options.format = format;
    write_image(image, folder / "whole", options);
    const std::string bytes = test::read_bytes(folder / "whole");
    test::write_bytes(folder / "cut", bytes.substr(0, bytes.size() / 2));
    EXPECT_THROW(read_image(folder / "cut"), ImageError);
  }
}

TEST(ImageIo, ReadingAFolderThrows) {
  ScratchFolder folder;
  EXPECT_THROW(read_image(folder.path()), ImageError);
}

}  // namespace
}  // namespace povtrace::image

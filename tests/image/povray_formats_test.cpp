// Our writers against Debian's povray 3.7 on the same linear image, byte for byte where POV-Ray's files carry
// no date or software name. The image reaches POV-Ray exactly: a Radiance file (whose values are exactly
// representable as floats) as an image_map seen face-on, one texel per pixel, by an orthographic camera, with
// ambient 1 and no lights, so POV-Ray's render equals the decoded file. Skipped when povray is not installed.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>

#include <gtest/gtest.h>

#include "renderer/image/bmp_io.hpp"
#include "renderer/image/hdr_io.hpp"
#include "renderer/image/tga_io.hpp"
#include "renderer/image/image.hpp"
#include "renderer/image/png_samples.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::image {
namespace {

using test::ScratchFolder;

constexpr int width = 40;   // wider than 8, so HDR scanlines are run-length encoded
constexpr int height = 30;

// A linear image with smooth ramps (runs for RLE), values above 1, flat areas and a black corner.
Image test_pattern() {
  Image image(width, height);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      float* p = image.pixel(x, y);
      const float u = float(x) / (width - 1), v = float(y) / (height - 1);
      p[0] = x < 6 ? 0.25f : u * 1.6f;
      p[1] = y < 4 ? 0.0f : v * v;
      p[2] = 0.5f * (1.0f - u) + 0.03f * float((x * 7 + y * 3) % 5);
      if (x < 3 && y < 3) p[0] = p[1] = p[2] = 0.0f;
    }
  }
  return image;
}

bool povray_installed() { return std::system("command -v povray > /dev/null 2>&1") == 0; }

struct Fixture {
  ScratchFolder folder;
  Image source;  // the image both renderers encode: test_pattern() after an RGBE round trip

  Fixture() {
    EncodeOptions hdr;
    hdr.format = FileFormat::hdr;
    write_image(test_pattern(), folder / "in.hdr", hdr);
    source = read_image(folder / "in.hdr");
    folder.write("scene.pov",
                 "#version 3.7;\n"
                 "global_settings { assumed_gamma 1.0 ambient_light 1 }\n"
                 "camera { orthographic location <20, 15, -10> look_at <20, 15, 0> right x*40 up y*30 }\n"
                 "box { <0, 0, 0>, <1, 1, 0.5> texture { pigment { image_map { hdr \"in.hdr\" } }\n"
                 "  finish { ambient 1 diffuse 0 } } scale <40, 30, 1> }\n");
  }

  // The same image half transparent: POV-Ray renders it (transmit all 0.5, background transparent under +UA)
  // as colour · 0.5 with alpha 0.5, premultiplied.
  Image half_transparent() const {
    Image image = source;
    image.has_alpha = true;
    for (std::size_t i = 0; i < image.rgba.size(); ++i) image.rgba[i] = i % 4 == 3 ? 0.5f : image.rgba[i] * 0.5f;
    return image;
  }
  void use_transparency() const {
    folder.write("scene.pov",
                 "#version 3.7;\n"
                 "global_settings { assumed_gamma 1.0 ambient_light 1 }\n"
                 "camera { orthographic location <20, 15, -10> look_at <20, 15, 0> right x*40 up y*30 }\n"
                 "polygon { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1>\n"
                 "  texture { pigment { image_map { hdr \"in.hdr\" transmit all 0.5 } }\n"
                 "  finish { ambient 1 diffuse 0 } } scale <40, 30, 1> }\n");
  }

  // POV-Ray's file for `flags` (e.g. "+FT +UA").
  std::string povray(const std::string& flags, const std::string& name) const {
    const std::string command = "cd '" + folder.path().string() + "' && povray -D -A +W40 +H30 " + flags + " +O" +
                                name + " scene.pov > povray.log 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << test::read_bytes(folder / "povray.log");
    return test::read_bytes(folder / name);
  }
};

EncodeOptions with_format(FileFormat format) {
  EncodeOptions options;
  options.format = format;
  return options;
}

// PNM without POV-Ray's "# Software" and "# Render Date" comment lines.
std::string without_comments(const std::string& pnm) {
  std::string out;
  for (std::size_t pos = 0; pos < pnm.size();) {
    const std::size_t end = pnm.find('\n', pos);
    if (pnm[pos] != '#' || end == std::string::npos) {
      if (pos == 0) {
        out += pnm.substr(0, end + 1);
        pos = end + 1;
        continue;
      }
      out += pnm.substr(pos);
      break;
    }
    pos = end + 1;
  }
  return out;
}

#define SKIP_WITHOUT_POVRAY() \
  if (!povray_installed()) GTEST_SKIP() << "povray is not installed"

TEST(PovrayFormats, ImageReachesPovrayExactly) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  const std::string theirs = f.povray("+FH", "pov.hdr");
  const Image read = decode_hdr(theirs);
  ASSERT_EQ(read.width, width);
  for (std::size_t i = 0; i < read.rgba.size(); ++i) ASSERT_EQ(read.rgba[i], f.source.rgba[i]) << i;
}

TEST(PovrayFormats, HdrScanlinesAreIdentical) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  const std::string theirs = f.povray("+FH", "pov.hdr");
  const std::string ours = encode_image(f.source, with_format(FileFormat::hdr));
  // Everything from the FORMAT line on (POV-Ray's earlier lines hold its name, the date and build comments).
  EXPECT_EQ(ours.substr(ours.find("FORMAT=")), theirs.substr(theirs.find("FORMAT=")));
}

TEST(PovrayFormats, PpmIsIdenticalButForComments) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  for (const int bits : {5, 8, 12, 16}) {
    const std::string flag = "+FP" + std::to_string(bits);
    EncodeOptions options = with_format(FileFormat::ppm);
    options.bits_per_channel = bits;
    EXPECT_EQ(encode_image(f.source, options), without_comments(f.povray(flag, "pov.ppm"))) << flag;
  }
}

// A PNG's chunks (type and data) without POV-Ray's tIME and tEXt (date, software), in file order.
std::string png_chunks(const std::string& png) {
  std::string out;
  for (std::size_t pos = 8; pos + 12 <= png.size();) {
    const auto byte = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(png[i])); };
    const std::uint32_t length = byte(pos) << 24 | byte(pos + 1) << 16 | byte(pos + 2) << 8 | byte(pos + 3);
    const std::string type = png.substr(pos + 4, 4);
    if (type != "tIME" && type != "tEXt") out += type + ":" + png.substr(pos + 8, length) + "\n";
    pos += 12 + length;
  }
  return out;
}

struct PngCase {
  const char* flags;
  int bits;
  bool grey;
  std::optional<double> file_gamma;
  Dither dither;
};

// The Targa header and pixels (all but POV-Ray's extension area and footer).
std::string tga_pixels(const std::string& tga) { return tga.substr(0, tga.size() - 495 - 26); }

// The extension area's fields other than software, comments and date: version, gamma, scan-line offset, alpha.
std::string tga_extension_fields(const std::string& tga) {
  const std::string ext = tga.substr(tga.size() - 495 - 26, 495);
  return ext.substr(0, 2) + ext.substr(467, 3) + ext.substr(478, 4) + ext.substr(490, 5);
}

TEST(PovrayFormats, TgaIsIdenticalButForMetadata) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  for (const bool rle : {false, true}) {
    const std::string theirs = f.povray(rle ? "+FC" : "+FT", "pov.tga");
    const std::string ours = encode_image(f.source, with_format(rle ? FileFormat::tga_rle : FileFormat::tga));
    EXPECT_EQ(tga_pixels(ours), tga_pixels(theirs)) << "RLE " << rle;
    EXPECT_EQ(tga_extension_fields(ours), tga_extension_fields(theirs)) << "RLE " << rle;
    EXPECT_EQ(ours.substr(ours.size() - 26 + 4), theirs.substr(theirs.size() - 26 + 4));  // footer signature
  }
}

TEST(PovrayFormats, BmpIsIdentical) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  EXPECT_EQ(encode_image(f.source, with_format(FileFormat::bmp)), f.povray("+FB", "pov.bmp"));
}

TEST(PovrayFormats, PngIsIdenticalButForTimeAndText) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  const PngCase cases[] = {
      {"+FN", 8, false, std::nullopt, Dither::none},
      {"+FN5", 5, false, std::nullopt, Dither::none},
      {"+FN7", 7, false, std::nullopt, Dither::none},
      {"+FN12", 12, false, std::nullopt, Dither::none},
      {"+FN16", 16, false, std::nullopt, Dither::none},
      {"+FNG", 8, true, std::nullopt, Dither::none},  // greyscale PNGs are always 16-bit
      {"+FN File_Gamma=2.0", 8, false, 2.0, Dither::none},
      {"+FN File_Gamma=1.0", 8, false, 1.0, Dither::none},
      {"+FN6 +THB2", 6, false, std::nullopt, Dither::bayer2},
      {"+FN6 +THB3", 6, false, std::nullopt, Dither::bayer3},
      {"+FN6 +THB4", 6, false, std::nullopt, Dither::bayer4},
      {"+FN6 +THD1", 6, false, std::nullopt, Dither::diffusion1d},
      {"+FN6 +THD2", 6, false, std::nullopt, Dither::diffusion2d},
      {"+FN6 +THFS", 6, false, std::nullopt, Dither::floyd_steinberg},
      {"+FN +THFS", 8, false, std::nullopt, Dither::floyd_steinberg},
  };
  for (const PngCase& c : cases) {
    EncodeOptions options = with_format(FileFormat::png);
    options.bits_per_channel = c.bits;
    options.grayscale = c.grey;
    options.file_gamma = c.file_gamma;
    options.dither = c.dither;
    const std::string ours = png_chunks(encode_image(f.source, options));
    EXPECT_NE(ours.find("IDAT:"), std::string::npos);
    EXPECT_EQ(ours, png_chunks(f.povray(c.flags, "pov.png"))) << c.flags;
  }
}

TEST(PovrayFormats, DitheringMatchesInEveryFormat) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  EncodeOptions options;
  options.dither = Dither::floyd_steinberg;
  options.format = FileFormat::bmp;  // rows bottom first: the error travels upwards
  EXPECT_EQ(encode_image(f.source, options), f.povray("+FB +THFS", "pov.bmp"));
  options.format = FileFormat::tga;
  EXPECT_EQ(tga_pixels(encode_image(f.source, options)), tga_pixels(f.povray("+FT +THFS", "pov.tga")));
  options.format = FileFormat::hdr;  // RGBE mantissas carry the error
  std::string ours = encode_image(f.source, options), theirs = f.povray("+FH +THFS", "pov.hdr");
  EXPECT_EQ(ours.substr(ours.find("FORMAT=")), theirs.substr(theirs.find("FORMAT=")));
  options.format = FileFormat::ppm;
  options.bits_per_channel = 5;
  options.dither = Dither::diffusion2d;
  EXPECT_EQ(encode_image(f.source, options), without_comments(f.povray("+FP5 +THD2", "pov.ppm")));
  options.format = FileFormat::tga_rle;  // stateless ordered dithering only: POV-Ray's RLE encodes pixels twice
  options.dither = Dither::bayer4;
  EXPECT_EQ(tga_pixels(encode_image(f.source, options)), tga_pixels(f.povray("+FC +THB4", "pov.tga")));
}

TEST(PovrayFormats, PgmIsLinearGrey) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  EncodeOptions options = with_format(FileFormat::ppm);
  options.grayscale = true;
  for (const int bits : {12, 16}) {
    options.bits_per_channel = bits;
    const std::string flag = "+FP" + std::to_string(bits) + " Grayscale_Output=on";
    EXPECT_EQ(encode_image(f.source, options), without_comments(f.povray(flag, "pov.ppm"))) << flag;
  }
  // At 8 bits POV-Ray declares maxval 255 but writes two bytes per sample (high byte 0); we write one.
  options.bits_per_channel = 8;
  const std::string ours = encode_image(f.source, options);
  const std::string theirs = without_comments(f.povray("+FPG", "pov.ppm"));
  const std::string header = "P5\n40 30\n255\n";
  ASSERT_EQ(ours.substr(0, header.size()), header);
  ASSERT_EQ(theirs.size(), header.size() + 2 * width * height);
  for (std::size_t i = 0; i < std::size_t(width) * height; ++i) {
    ASSERT_EQ(theirs[header.size() + 2 * i], 0);
    ASSERT_EQ(ours[header.size() + i], theirs[header.size() + 2 * i + 1]) << i;
  }
}

// POV-Ray's JPEG differs only in its comment (date, software): the rest, from the first marker after the
// comment on, is libjpeg's output for the same samples and settings.
std::string jpeg_after_comment(const std::string& jpeg) {
  const std::size_t com = jpeg.find("\xff\xfe");
  if (com == std::string::npos) return "no comment";
  const std::size_t length = (static_cast<unsigned char>(jpeg[com + 2]) << 8) | static_cast<unsigned char>(jpeg[com + 3]);
  return jpeg.substr(0, com) + jpeg.substr(com + 2 + length);
}

TEST(PovrayFormats, JpegIsIdenticalButForComment) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  EncodeOptions options = with_format(FileFormat::jpeg);
  EXPECT_EQ(jpeg_after_comment(encode_image(f.source, options)), jpeg_after_comment(f.povray("+FJ", "pov.jpg")));
  options.jpeg_quality = 40;
  EXPECT_EQ(jpeg_after_comment(encode_image(f.source, options)),
            jpeg_after_comment(f.povray("+FJ Compression=40", "pov.jpg")));
  f.use_transparency();
  EXPECT_EQ(jpeg_after_comment(encode_image(f.half_transparent(), with_format(FileFormat::jpeg))),
            jpeg_after_comment(f.povray("+FJ +UA", "pov.jpg")));  // composited over black
}

TEST(PovrayFormats, AlphaFormatsAreIdentical) {
  SKIP_WITHOUT_POVRAY();
  Fixture f;
  f.use_transparency();
  const Image image = f.half_transparent();
  EXPECT_EQ(encode_image(image, with_format(FileFormat::bmp)), f.povray("+FB +UA", "pov.bmp"));
  EXPECT_EQ(png_chunks(encode_image(image, with_format(FileFormat::png))), png_chunks(f.povray("+FN +UA", "pov.png")));
  EncodeOptions grey = with_format(FileFormat::png);
  grey.grayscale = true;
  EXPECT_EQ(png_chunks(encode_image(image, grey)), png_chunks(f.povray("+FNG +UA", "pov.png")));
  for (const bool rle : {false, true}) {
    const std::string theirs = f.povray(rle ? "+FC +UA" : "+FT +UA", "pov.tga");
    const std::string ours = encode_image(image, with_format(rle ? FileFormat::tga_rle : FileFormat::tga));
    EXPECT_EQ(tga_pixels(ours), tga_pixels(theirs)) << "RLE " << rle;
    EXPECT_EQ(tga_extension_fields(ours), tga_extension_fields(theirs)) << "RLE " << rle;
  }
}

}  // namespace
}  // namespace povtrace::image

// Our writers against Debian's povray 3.7 on the same linear image, byte for byte where POV-Ray's files carry
// no date or software name. The image reaches POV-Ray exactly: a Radiance file (whose values are exactly
// representable as floats) as an image_map seen face-on, one texel per pixel, by an orthographic camera, with
// ambient 1 and no lights, so POV-Ray's render equals the decoded file. Skipped when povray is not installed.
#include <sys/wait.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "renderer/image/hdr_io.hpp"
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

}  // namespace
}  // namespace povtrace::image

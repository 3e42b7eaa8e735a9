// density_file df3 (POV-Ray 3.7's Read_Density_File and Parse_Pattern): the DF3 reader (runtime/density_file.hpp)
// and the pattern in the SDL — where the file is looked for, what is recorded, and the errors with their positions.
#include <gtest/gtest.h>

#include <fstream>

#include "runtime/density_file.hpp"
#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

// The six header bytes: the sizes as big-endian 16-bit numbers.
std::vector<std::uint8_t> header(int x, int y, int z) {
  std::vector<std::uint8_t> h;
  for (int v : {x, y, z}) {
    h.push_back(static_cast<std::uint8_t>(v >> 8));
    h.push_back(static_cast<std::uint8_t>(v));
  }
  return h;
}

std::vector<std::uint8_t> file_of(int x, int y, int z, const std::vector<std::uint8_t>& data) {
  std::vector<std::uint8_t> bytes = header(x, y, z);
  bytes.insert(bytes.end(), data.begin(), data.end());
  return bytes;
}

// The message of the DensityFileError parsing `bytes` raises ("" when it parses).
std::string reader_error(const std::vector<std::uint8_t>& bytes) {
  try {
    df3::parse_density_file(bytes, "t.df3");
  } catch (const df3::DensityFileError& e) {
    return e.what();
  }
  return "";
}

void write_file(const std::filesystem::path& path, const std::vector<std::uint8_t>& bytes) {
  std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                               static_cast<std::streamsize>(bytes.size()));
}

// ---- the reader ----

TEST(DensityFileReader, EightBitVoxelsRunXFastestThenYThenZ) {
  std::vector<std::uint8_t> data(2 * 3 * 4);
  for (std::size_t i = 0; i < data.size(); ++i) data[i] = static_cast<std::uint8_t>(10 * i);
  const DensityGrid g = df3::parse_density_file(file_of(2, 3, 4, data), "t.df3");
  EXPECT_EQ(g.size_x, 2u);
  EXPECT_EQ(g.size_y, 3u);
  EXPECT_EQ(g.size_z, 4u);
  EXPECT_EQ(g.bytes_per_voxel, 1);
  EXPECT_EQ(g.file, "t.df3");
  // Voxel (1, 2, 3) is number 1 + 2·2 + 3·2·3 = 23: stored 230, read as 230 / 255.
  EXPECT_EQ(df3::voxel_value(g, 1 + 2 * 2 + 3 * 2 * 3), 230.0 / 255.0);
  EXPECT_EQ(df3::voxel_value(g, 0), 0.0);
}

TEST(DensityFileReader, SixteenBitVoxelsAreBigEndianOver65535) {
  const DensityGrid g = df3::parse_density_file(file_of(3, 1, 1, {0x12, 0x34, 0xff, 0xff, 0x00, 0x01}), "t.df3");
  EXPECT_EQ(g.bytes_per_voxel, 2);
  EXPECT_EQ(df3::voxel_value(g, 0), 0x1234 / 65535.0);
  EXPECT_EQ(df3::voxel_value(g, 1), 1.0);
  EXPECT_EQ(df3::voxel_value(g, 2), 1 / 65535.0);
}

TEST(DensityFileReader, ThirtyTwoBitVoxelsAreBigEndianOverUintMax) {
  const DensityGrid g =
      df3::parse_density_file(file_of(1, 2, 1, {0x80, 0x00, 0x00, 0x01, 0xff, 0xff, 0xff, 0xff}), "t.df3");
  EXPECT_EQ(g.bytes_per_voxel, 4);
  EXPECT_EQ(df3::voxel_value(g, 0), 2147483649.0 / 4294967295.0);
  EXPECT_EQ(df3::voxel_value(g, 1), 1.0);
}

// The width is whichever of 4, 2, 1 bytes makes the voxels fill the file exactly: 8 bytes are 8 voxels of 8 bits for
// a 2x2x2 grid, 2 voxels of 32 bits for a 2x1x1 grid.
TEST(DensityFileReader, TheWidthComesFromTheLength) {
  const std::vector<std::uint8_t> data(8, 0x40);
  EXPECT_EQ(df3::parse_density_file(file_of(2, 2, 2, data), "t.df3").bytes_per_voxel, 1);
  EXPECT_EQ(df3::parse_density_file(file_of(2, 1, 2, data), "t.df3").bytes_per_voxel, 2);
  EXPECT_EQ(df3::parse_density_file(file_of(2, 1, 1, data), "t.df3").bytes_per_voxel, 4);
}

TEST(DensityFileReader, AFileShorterThanItsHeaderIsAnError) {
  for (std::size_t n = 0; n < 6; ++n) {
    const std::string e = reader_error(std::vector<std::uint8_t>(n, 1));
    EXPECT_NE(e.find("too short for its header"), std::string::npos) << n << " bytes: " << e;
  }
}

TEST(DensityFileReader, VoxelDataOfAnyOtherLengthIsAnError) {
  // 2x2x2 voxels need 8, 16 or 32 bytes: a byte too few, a byte too many and 24 bytes (3 per voxel) are refused.
  for (std::size_t n : {7u, 9u, 24u}) {
    const std::string e = reader_error(file_of(2, 2, 2, std::vector<std::uint8_t>(n, 1)));
    EXPECT_NE(e.find("invalid density file size"), std::string::npos) << n << " bytes: " << e;
    EXPECT_NE(e.find("2x2x2 voxels"), std::string::npos) << e;
  }
  EXPECT_EQ(reader_error(file_of(2, 2, 2, std::vector<std::uint8_t>(16, 1))), "");
}

// POV-Ray accepts a grid with a zero size and no voxel data (the pattern is then 0 everywhere).
TEST(DensityFileReader, AnEmptyGridIsAcceptedOnlyWithoutData) {
  const DensityGrid g = df3::parse_density_file(header(0, 4, 4), "t.df3");
  EXPECT_EQ(g.size_x, 0u);
  EXPECT_TRUE(g.voxels.empty());
  EXPECT_NE(reader_error(file_of(0, 4, 4, {1})).find("invalid density file size"), std::string::npos);
}

TEST(DensityFileReader, ReadsAFileAndReportsAMissingOne) {
  ScratchFolder folder;
  write_file(folder / "g.df3", file_of(1, 1, 2, {0, 255}));
  const DensityGrid g = df3::read_density_file(folder / "g.df3");
  EXPECT_EQ(g.size_z, 2u);
  EXPECT_EQ(df3::voxel_value(g, 1), 1.0);
  EXPECT_EQ(g.file, (folder / "g.df3").string());
  EXPECT_THROW(df3::read_density_file(folder / "none.df3"), df3::DensityFileError);
}

// ---- the pattern in the SDL ----

// A scratch folder made the working directory, with a 2x3x4 8-bit file "grid.df3".
class DensityScene {
 public:
  DensityScene() : cwd_(folder_.path()) {
    write_file(folder_ / "grid.df3", file_of(2, 3, 4, std::vector<std::uint8_t>(24, 7)));
  }
  const ScratchFolder& folder() const { return folder_; }

 private:
  ScratchFolder folder_;
  WorkingDirectory cwd_;
};

const Pigment& pigment_of(const SceneDescription& s) { return s.objects.at(0).texture->layers.back().pigment; }

TEST(DensityFileParse, APigmentHoldsTheGridAndTheInterpolation) {
  DensityScene dir;
  const SceneDescription s = parse(
      "#version 3.7;\n"
      "box { 0, 1 pigment { density_file df3 \"grid.df3\" interpolate 1 color_map { [0 rgb 0] [1 rgb 1] } } }\n");
  const Pigment& p = pigment_of(s);
  ASSERT_EQ(p.pattern, PatternKind::density_file);
  ASSERT_TRUE(p.density_file);
  EXPECT_EQ(p.density_file->size_x, 2u);
  EXPECT_EQ(p.density_file->size_z, 4u);
  EXPECT_EQ(p.density_file->file, (dir.folder() / "grid.df3").string());
  EXPECT_EQ(p.density_interpolation, 1);
  EXPECT_EQ(p.entries.size(), 2u);
  EXPECT_FALSE(p.unsupported);
}

// POV-Ray stores (int)N; a new density_file starts at 0 again, a copied pigment keeps its interpolation.
TEST(DensityFileParse, InterpolateIsTruncatedAndResetByANewFile) {
  DensityScene dir;
  const std::string prelude = "#version 3.7;\n#declare P = pigment { density_file df3 \"grid.df3\" interpolate 2.9 }\n";
  EXPECT_EQ(pigment_of(parse(prelude + "box { 0, 1 pigment { P } }")).density_interpolation, 2);
  EXPECT_EQ(pigment_of(parse(prelude + "box { 0, 1 pigment { P density_file df3 \"grid.df3\" } }"))
                .density_interpolation, 0);
  EXPECT_EQ(pigment_of(parse(prelude + "box { 0, 1 pigment { P interpolate -1.5 } }")).density_interpolation, -1);
}

TEST(DensityFileParse, TheExtensionMayBeLeftOut) {
  DensityScene dir;
  const SceneDescription s = parse("#version 3.7;\nbox { 0, 1 pigment { density_file df3 \"grid\" } }\n");
  const Pigment& p = pigment_of(s);
  ASSERT_TRUE(p.density_file);
  EXPECT_EQ(p.density_file->file, (dir.folder() / "grid.df3").string());
}

TEST(DensityFileParse, TheFileIsFoundInALibraryPath) {
  ScratchFolder lib;
  write_file(lib / "lib.df3", file_of(1, 1, 1, {9}));
  ParseOptions o;
  o.library_paths = {lib.path()};
  o.message_sink = [](const std::string&) {};
  const SceneDescription s =
      parse_scene_text("#version 3.7;\nbox { 0, 1 pigment { density_file df3 \"lib.df3\" } }\n", "test.pov", o);
  EXPECT_EQ(pigment_of(s).density_file->file, (lib / "lib.df3").string());
}

TEST(DensityFileParse, AMissingFileIsAnErrorAtItsName) {
  DensityScene dir;
  const ParseError e = parse_error("#version 3.7;\nbox { 0, 1 pigment { density_file df3 \"none.df3\" } }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 39);
  EXPECT_NE(e.bare_message().find("cannot find the density file 'none.df3'"), std::string::npos) << e.what();
}

TEST(DensityFileParse, AMalformedFileIsAnErrorAtItsName) {
  DensityScene dir;
  write_file(dir.folder() / "short.df3", {0, 2, 0});
  write_file(dir.folder() / "odd.df3", file_of(2, 2, 2, std::vector<std::uint8_t>(5, 0)));
  ParseError e = parse_error("#version 3.7;\nbox { 0, 1 pigment { density_file df3 \"short.df3\" } }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 39);
  EXPECT_NE(e.bare_message().find("too short for its header"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nbox { 0, 1 pigment { density_file df3 \"odd.df3\" } }\n");
  EXPECT_NE(e.bare_message().find("invalid density file size"), std::string::npos) << e.what();
}

TEST(DensityFileParse, TheTypeKeywordAndAPatternForInterpolateAreRequired) {
  DensityScene dir;
  ParseError e = parse_error("#version 3.7;\nbox { 0, 1 pigment { density_file \"grid.df3\" } }\n");
  EXPECT_NE(e.bare_message().find("'df3'"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nbox { 0, 1 pigment { bozo interpolate 1 } }\n");
  EXPECT_NE(e.bare_message().find("non-density_file"), std::string::npos) << e.what();
}

// Wherever a pattern is: a media density, a normal, a patterned texture, pattern and pigment functions.
TEST(DensityFileParse, ItIsAPatternEverywhere) {
  DensityScene dir;
  const SceneDescription s = parse(
      "#version 3.7;\n"
      "#declare F = function { pattern { density_file df3 \"grid.df3\" interpolate 2 } }\n"
      "#declare G = function { pigment { density_file df3 \"grid.df3\" } }\n"
      "box { 0, 1 hollow pigment { rgbt 1 }\n"
      "  interior { media { emission 1 density { density_file df3 \"grid.df3\" interpolate 1 } } } }\n"
      "box { 0, 1 normal { density_file df3 \"grid.df3\" 0.5 interpolate 2 } }\n"
      "box { 0, 1 texture { density_file df3 \"grid.df3\"\n"
      "  texture_map { [0 pigment { rgb 0 }] [1 pigment { rgb 1 }] } } }\n");
  ASSERT_EQ(s.objects.size(), 3u);
  const Pigment& density = s.objects[0].interior->media->at(0).densities.at(0);
  EXPECT_EQ(density.pattern, PatternKind::density_file);
  EXPECT_EQ(density.density_interpolation, 1);
  const Normal& n = *s.objects[1].texture->layers.back().normal;
  EXPECT_EQ(n.pattern.pattern, PatternKind::density_file);
  EXPECT_EQ(n.pattern.density_interpolation, 2);
  EXPECT_EQ(n.amount, 0.5);
  ASSERT_TRUE(s.objects[2].texture->patterned());
  EXPECT_EQ(s.objects[2].texture->pattern->pattern.pattern, PatternKind::density_file);
}

// A density povtrace cannot render must not be left out of the media silently: the object, or the scene's
// atmospheric media, is refused (pavement stands for any pattern povtrace does not render yet).
TEST(MediaDensityParse, AnUnsupportedDensityRefusesTheObjectOrTheAtmosphere) {
  ParseError e = parse_error(
      "#version 3.7;\nbox { 0, 1 hollow interior { media { emission 1 density { pavement } } } }\n");
  EXPECT_NE(e.bare_message().find("unsupported: the density item 'pavement'"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nmedia { emission 1 density { pavement } }\n");
  EXPECT_NE(e.bare_message().find("unsupported: the density item 'pavement'"), std::string::npos) << e.what();
  EXPECT_NE(e.bare_message().find("atmospheric media"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace povtrace::test

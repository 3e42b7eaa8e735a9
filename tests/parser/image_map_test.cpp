// image_map in the SDL (POV-Ray 3.7 Parse_Image, Parse_Image_Map): items as recorded, the gamma handling of the
// point where the image is parsed, and the errors with their positions.
#include <gtest/gtest.h>

#include <fstream>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

// A scratch folder with a file "tex.png" (the parser only checks that it exists), made the working directory.
class ImageScene {
 public:
  ImageScene() : cwd_(folder_.path()) { std::ofstream(folder_ / "tex.png") << "x"; }
  SceneDescription parse_scene(const std::string& text) { return parse(text); }
  std::string path() const { return (folder_ / "tex.png").string(); }

 private:
  ScratchFolder folder_;
  WorkingDirectory cwd_;
};

const Pigment& pigment_of(const SceneDescription& s, std::size_t i = 0) {
  return s.objects.at(i).texture->layers.back().pigment;
}

TEST(ImageMapParse, ItemsAreRecorded) {
  ImageScene dir;
  const SceneDescription s = dir.parse_scene(
      "#version 3.7;\n"
      "plane { z, 0 pigment { image_map { png \"tex.png\" map_type 1 once interpolate 2 use_index\n"
      "  filter all 0.25 transmit 3, 0.5 repeat <2, 3> offset 0.5 } scale 2 } }\n");
  const Pigment& p = pigment_of(s);
  ASSERT_EQ(p.pattern, PatternKind::image_map);
  ASSERT_TRUE(p.image);
  const ImageMap& m = *p.image;
  EXPECT_EQ(m.file, dir.path());   // found in the working directory
  EXPECT_EQ(m.file_loc.line, 2);
  EXPECT_EQ(m.file_loc.column, 40);
  EXPECT_EQ(m.map_type, 1);
  EXPECT_TRUE(m.once);
  EXPECT_EQ(m.interpolate, 2);
  EXPECT_TRUE(m.use_index);
  ASSERT_EQ(m.channels.size(), 2u);
  EXPECT_FALSE(m.channels[0].transmit);
  EXPECT_EQ(m.channels[0].index, -1);
  EXPECT_EQ(m.channels[0].value, 0.25);
  EXPECT_TRUE(m.channels[1].transmit);
  EXPECT_EQ(m.channels[1].index, 3);
  EXPECT_EQ(m.channels[1].value, 0.5);
  EXPECT_TRUE(m.has_filter);
  EXPECT_EQ(m.repeat_u, 2);
  EXPECT_EQ(m.repeat_v, 3);
  EXPECT_EQ(m.offset_u, 0.5);   // a float is promoted to both
  EXPECT_EQ(m.offset_v, 0.5);
  EXPECT_EQ(p.world_from_pattern.m[0][0], 2);
  EXPECT_EQ(p.frequency, 0.0);
}

TEST(ImageMapParse, GammaHandlingIsTheScenesAtThatPoint) {
  ImageScene dir;
  const std::string map = "pigment { image_map { \"tex.png\" } }";
  auto mode = [&](const std::string& prelude) {
    return pigment_of(dir.parse_scene(prelude + "\nsphere { 0, 1 " + map + " }\n")).image->gamma;
  };
  EXPECT_EQ(mode("").mode, ImageGammaMode::none);   // no #version: POV-Ray 3.62 rules, no assumed_gamma
  EXPECT_EQ(mode("#version 3.7;").mode, ImageGammaMode::file_or_srgb);
  EXPECT_EQ(mode("#version 3.6;").mode, ImageGammaMode::none);
  const ImageGamma old = mode("#version 3.6; global_settings { assumed_gamma 2.2 }");
  EXPECT_EQ(old.mode, ImageGammaMode::file_or_working);
  EXPECT_EQ(old.working, 2.2);
  EXPECT_EQ(mode("global_settings { assumed_gamma 1 } #version 3.7;").mode, ImageGammaMode::file_or_srgb);
  // An assumed_gamma after the image does not change it.
  const SceneDescription late = dir.parse_scene("#version 3.6;\nsphere { 0, 1 " + map +
                                                " }\nglobal_settings { assumed_gamma 1 }\n");
  EXPECT_EQ(pigment_of(late).image->gamma.mode, ImageGammaMode::none);
  const ImageGamma given = pigment_of(dir.parse_scene(
      "#version 3.7;\nsphere { 0, 1 pigment { image_map { png \"tex.png\" gamma 2.2 premultiplied off } } }\n"))
                               .image->gamma;
  EXPECT_TRUE(given.given);
  EXPECT_EQ(given.given_gamma, 2.2);
  const ImageGamma srgb = pigment_of(dir.parse_scene(
      "#version 3.7;\nsphere { 0, 1 pigment { image_map { png \"tex.png\" gamma srgb } } }\n")).image->gamma;
  EXPECT_TRUE(srgb.given_srgb);
}

TEST(ImageMapParse, ErrorsArePlaced) {
  ImageScene dir;
  ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { png \"none.png\" } } }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 41);
  EXPECT_NE(e.bare_message().find("cannot open the image file 'none.png'"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.png\" interpolate 1 } } }\n");
  EXPECT_EQ(e.location().column, 47);
  EXPECT_NE(e.bare_message().find("invalid interpolate value"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.png\" map_type 3 } } }\n");
  EXPECT_NE(e.bare_message().find("invalid map_type value"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.png\" repeat <1, 0> } } }\n");
  EXPECT_NE(e.bare_message().find("zero or negative image repeat"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.png\" alpha all 1 } } }\n");
  EXPECT_NE(e.bare_message().find("'alpha' is discontinued"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.png\" } color_map { [0 rgb 1] } } }\n");
  EXPECT_NE(e.bare_message().find("cannot use color_map with this pattern type"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.xyz\" } } }\n");
  EXPECT_NE(e.bare_message().find("could not determine a valid image file type"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 normal { image_map { \"tex.png\" } } }\n");
  EXPECT_EQ(e.location().column, 24);
  EXPECT_NE(e.bare_message().find("image_map can only be used in a pigment"), std::string::npos) << e.what();
}

TEST(ImageMapParse, OtherImageTypesAreRefusedByNameWhereTheObjectIsPlaced) {
  ImageScene dir;
  ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { gif \"tex.gif\" } } }\n");
  EXPECT_NE(e.bare_message().find("image_map from a gif image"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.jpg\" once } } }\n");
  EXPECT_NE(e.bare_message().find("image_map from a .jpg image"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { function 8, 8 { x } } } }\n");
  EXPECT_NE(e.bare_message().find("an image made from a function"), std::string::npos) << e.what();
  e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { image_map { \"tex.png\" premultiplied on } } }\n");
  EXPECT_NE(e.bare_message().find("an image read as premultiplied"), std::string::npos) << e.what();
}

// image_pattern { } (Parse_Image_Pattern): a pattern like any other (its colour_map and modifiers follow), the image
// read raw, use_alpha recorded (use_colour and use_index give the grey again), frequency 0.
TEST(ImagePatternParse, ItemsAndPatternModifiers) {
  ImageScene dir;
  const SceneDescription s = dir.parse_scene(
      "#version 3.7;\n"
      "plane { z, 0 pigment { image_pattern { png \"tex.png\" map_type 2 once interpolate 4 use_alpha repeat 2 }\n"
      "  colour_map { [0 rgb 0] [1 rgb x] } scale 3 } }\n"
      "plane { z, 0 pigment { image_pattern { png \"tex.png\" use_alpha use_index } } }\n"
      "plane { z, 0 normal { image_pattern { png \"tex.png\" } 0.5 } }\n");
  const Pigment& p = pigment_of(s);
  ASSERT_EQ(p.pattern, PatternKind::image_pattern);
  ASSERT_TRUE(p.image);
  EXPECT_EQ(p.image->map_type, 2);
  EXPECT_TRUE(p.image->once);
  EXPECT_EQ(p.image->interpolate, 4);
  EXPECT_TRUE(p.image->use_alpha);
  EXPECT_EQ(p.image->repeat_u, 2.0);
  EXPECT_EQ(p.image->gamma.mode, ImageGammaMode::none);   // read raw, as bump_map images
  EXPECT_EQ(p.frequency, 0.0);
  EXPECT_EQ(p.entries.size(), 2u);
  EXPECT_FALSE(pigment_of(s, 1).image->use_alpha);
  const Normal& n = *s.objects.at(2).texture->layers.back().normal;
  EXPECT_EQ(n.pattern.pattern, PatternKind::image_pattern);
  EXPECT_EQ(n.amount, 0.5);
  const ParseError e = parse_error("#version 3.7;\nplane { z, 0 pigment { image_pattern { png \"tex.png\" "
                                   "filter all 0.5 } } }\n");
  EXPECT_NE(e.bare_message().find("use_alpha, repeat, offset or '}' in image_pattern"), std::string::npos)
      << e.bare_message();
}

TEST(UvMappingParse, PigmentUvMappingWrapsTheRestOfTheBlock) {
  const SceneDescription s =
      parse("#version 3.7;\nsphere { 0, 1 pigment { uv_mapping checker rgb 1, rgb 0 scale 0.25 } }\n");
  const Pigment& p = pigment_of(s);
  ASSERT_EQ(p.pattern, PatternKind::uv_mapping);
  ASSERT_EQ(p.entries.size(), 1u);
  ASSERT_TRUE(p.entries[0].pigment);
  EXPECT_EQ(p.entries[0].pigment->pattern, PatternKind::checker);
  EXPECT_EQ(p.entries[0].pigment->world_from_pattern.m[0][0], 0.25);
  ParseError e = parse_error("#version 3.7;\nsky_sphere { pigment { uv_mapping gradient y } }\n");
  EXPECT_NE(e.bare_message().find("uv_mapping"), std::string::npos) << e.what();
}

}  // namespace
}  // namespace povtrace::test

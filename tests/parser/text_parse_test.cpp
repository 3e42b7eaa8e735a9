// text { } in the SDL: the fonts are found like include files, errors are located, min_extent/max_extent and
// inside() of text objects give what POV-Ray 3.7.0.10 prints for the same scene (#debug output recorded from it).
#include <gtest/gtest.h>

#include <fstream>

#include "parse_helpers.hpp"

namespace {

using namespace povtrace;
using namespace povtrace::test;

TEST(TextParse, TextIsAnObjectWithOneGlyphPerCharacter) {
  const SceneDescription s = parse("text { ttf \"timrom.ttf\" \"Hi there\" 0.25, <0.1, 0, 0> }");
  ASSERT_EQ(s.objects.size(), 1u);
  const auto* text = std::get_if<Text>(&s.objects[0].shape);
  ASSERT_NE(text, nullptr);
  EXPECT_EQ(text->glyphs.size(), 8u);
  EXPECT_EQ(text->thickness, 0.25);
  // POV-Ray's anti-crack rotation of 0.001° about each axis comes before any object modifier.
  EXPECT_EQ(s.objects[0].world_from_object, Matrix::rotation({0.001, 0.001, 0.001}));
}

TEST(TextParse, ExtentsMatchPovRay) {
  // POV-Ray 3.7.0.10 prints "-0.000012708,-0.010003490,-0.000030514 | 1.681003571,0.728029311,0.200013697".
  EXPECT_EQ(debug_output("#declare T = text { ttf \"cyrvetic.ttf\" \"Pov\" 0.2, <0.05,0,0> }\n"
                         "#debug concat(vstr(3, min_extent(T), \",\", 0, 9), \" | \", "
                         "vstr(3, max_extent(T), \",\", 0, 9))"),
            "-0.000012708,-0.010003490,-0.000030514 | 1.681003571,0.728029311,0.200013697");
}

TEST(TextParse, InsideIsTheUnionOfTheGlyphSolids) {
  const std::string t = "#declare T = text { ttf \"crystal.ttf\" \"l\" 1, 0 }\n";
  // crystal's 'l': a stem (x 0.151 … 0.222 once shifted by −xMin) on a foot. POV-Ray prints "1001".
  EXPECT_EQ(debug_output(t + "#debug concat(str(inside(T, <0.19, 0.3, 0.5>), 0, 0), str(inside(T, <0.19, 0.3, 1.5>), 0, 0),"
                             " str(inside(T, <0.3, 0.3, 0.5>), 0, 0), str(inside(T, <0.05, 0.03, 0.5>), 0, 0))"),
            "1001");
}

TEST(TextParse, InternalFontsAreTheShippedFiles) {
  const SceneDescription a = parse("text { internal 1 \"A\" 1, 0 }");
  const SceneDescription b = parse("text { ttf \"timrom.ttf\" \"A\" 1, 0 }");
  const auto& ga = std::get<Text>(a.objects[0].shape).glyphs[0];
  const auto& gb = std::get<Text>(b.objects[0].shape).glyphs[0];
  EXPECT_EQ(ga.outline->contours.size(), gb.outline->contours.size());
  EXPECT_EQ(ga.outline->contours[0].x, gb.outline->contours[0].x);
}

TEST(TextParse, ErrorsAreLocated) {
  ParseError e = parse_error("text { ttf \"nosuchfont.ttf\" \"x\" 1, 0 }");
  EXPECT_EQ(e.location().line, 1);
  EXPECT_EQ(e.location().column, 12);
  EXPECT_NE(std::string(e.what()).find("cannot find font file \"nosuchfont.ttf\""), std::string::npos);
  e = parse_error("text { sphere \"x\" 1, 0 }");
  EXPECT_EQ(e.location().column, 8);
  EXPECT_NE(std::string(e.what()).find("ttf or internal"), std::string::npos);
  e = parse_error("global_settings { charset latin1 }");
  EXPECT_NE(std::string(e.what()).find("ascii, utf8 or sys"), std::string::npos);
}

TEST(TextParse, ANonFontFileIsALocatedError) {
  ScratchFolder dir;
  const auto fake = dir.path() / "fake.ttf";
  { std::ofstream(fake) << "this is not a font"; }
  const ParseError e = parse_error("\n  text { ttf \"" + fake.string() + "\" \"x\" 1, 0 }");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 14);
  EXPECT_NE(std::string(e.what()).find("cannot read TrueType font file"), std::string::npos);
}

}  // namespace

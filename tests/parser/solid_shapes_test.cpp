// superellipsoid, blob, lathe, prism, sor and height_field in the SDL: parameters as written, POV-Ray's defaults
// and refusals with their positions.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Object& only_object(const SceneDescription& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0);
}

TEST(SolidShapes, SuperellipsoidExponents) {
  auto s = parse("#version 3.7;\nsuperellipsoid { <0.25, 1.5> translate x }\n");
  auto se = std::get<Superellipsoid>(only_object(s).shape);
  EXPECT_EQ(se.e, 0.25);
  EXPECT_EQ(se.n, 1.5);
  EXPECT_EQ(only_object(s).world_from_object, Matrix::translation({1, 0, 0}));
  s = parse("#version 3.7;\n#declare S = superellipsoid { 0.5 }\nobject { S }\n");   // a float stands for both
  se = std::get<Superellipsoid>(only_object(s).shape);
  EXPECT_EQ(se.e, 0.5);
  EXPECT_EQ(se.n, 0.5);
  const ParseError e = parse_error("#version 3.7;\nsuperellipsoid { <1, 2, 3> }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 18);
  EXPECT_NE(e.bare_message().find("expected a 2-D vector"), std::string::npos) << e.bare_message();
}

TEST(SolidShapes, HeightFieldImageAndOptions) {
  auto s = parse("#version 3.7;\nheight_field { png \"hills.png\" gamma 1 smooth water_level 0.25 hierarchy off "
                 "translate y }\n");
  auto h = std::get<HeightField>(only_object(s).shape);
  EXPECT_EQ(h.file, "hills.png");   // not found: kept as written, the renderer reports it
  EXPECT_EQ(h.file_loc.line, 2);
  EXPECT_EQ(h.file_loc.column, 20);
  EXPECT_TRUE(h.smooth);
  EXPECT_EQ(h.water_level, 0.25);
  s = parse("#version 3.7;\nheight_field { \"a.PNG\" }\n");   // the type from the extension
  EXPECT_FALSE(std::get<HeightField>(only_object(s).shape).smooth);
  s = parse("#version 1.0;\nheight_field { png \"a.png\" water_level 64 }\n");   // before 2.0: W / 256
  EXPECT_EQ(std::get<HeightField>(only_object(s).shape).water_level, 0.25);
}

TEST(SolidShapes, HeightFieldsPovtraceDoesNotReadAreRefusedByName) {
  ParseError e = parse_error("#version 3.7;\nheight_field { tga \"a.tga\" smooth }\n");
  EXPECT_NE(e.bare_message().find("a height_field read from a tga image"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nheight_field { \"a.jpg\" }\n");
  EXPECT_NE(e.bare_message().find("read from a '.jpg' image"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nheight_field { function 20, 20 { x * y } smooth }\n");
  EXPECT_NE(e.bare_message().find("a height_field made from a function"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nheight_field { png \"a.png\" gamma 2.2 }\n");
  EXPECT_NE(e.bare_message().find("decoded with a gamma"), std::string::npos) << e.bare_message();
}

}  // namespace
}  // namespace povtrace::test

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

}  // namespace
}  // namespace povtrace::test

// cylinder, cone, disc and torus in the SDL: parameters and defaults as written, optional commas, `open` only after
// the parameters, the optional hole radius, `sturm` only on a torus, and POV-Ray's refusals with their positions.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Object& only_object(const SceneDescription& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0);
}

TEST(QuadricShapes, CylinderParametersAndOpen) {
  auto s = parse("#version 3.7;\ncylinder { <1,2,3>, <4,5,6>, 0.5 }\n");
  const auto& c = std::get<Cylinder>(only_object(s).shape);
  EXPECT_EQ(c.end1, (Vec3{1, 2, 3}));
  EXPECT_EQ(c.end2, (Vec3{4, 5, 6}));
  EXPECT_EQ(c.radius, 0.5);
  EXPECT_FALSE(c.open);
  s = parse("#version 3.7;\ncylinder { 0 y 2 open translate x }\n");   // commas are optional
  const auto& o = std::get<Cylinder>(only_object(s).shape);
  EXPECT_TRUE(o.open);
  EXPECT_EQ(o.radius, 2);
  EXPECT_EQ(only_object(s).world_from_object, Matrix::translation({1, 0, 0}));
}

TEST(QuadricShapes, ConeParameters) {
  const auto s = parse("#version 3.7;\ncone { <0,0,0>, 1, <0,2,0>, 0 open pigment { rgb 1 } }\n");
  const auto& c = std::get<Cone>(only_object(s).shape);
  EXPECT_EQ(c.radius1, 1);
  EXPECT_EQ(c.end2, (Vec3{0, 2, 0}));
  EXPECT_EQ(c.radius2, 0);
  EXPECT_TRUE(c.open);
}

TEST(QuadricShapes, DiscWithAndWithoutHole) {
  auto s = parse("#version 3.7;\ndisc { <0,1,0>, <0,2,0>, 3 }\n");
  auto d = std::get<Disc>(only_object(s).shape);
  EXPECT_EQ(d.normal, (Vec3{0, 1, 0}));   // normalised
  EXPECT_EQ(d.radius, 3);
  EXPECT_EQ(d.hole_radius, 0);
  s = parse("#version 3.7;\n#declare H = 0.5;\ndisc { 0, z, 3, H rotate x*10 }\n");
  d = std::get<Disc>(only_object(s).shape);
  EXPECT_EQ(d.hole_radius, 0.5);
  s = parse("#version 3.7;\ndisc { 0, z, 3, -0.5 }\n");
  EXPECT_EQ(std::get<Disc>(only_object(s).shape).hole_radius, -0.5);
}

TEST(QuadricShapes, DiscWithZeroNormalWarns) {
  Messages m;
  const auto s = parse("#version 3.7;\ndisc { 0, 0, 1 }\n", &m);
  EXPECT_EQ(std::get<Disc>(only_object(s).shape).normal, (Vec3{}));
  EXPECT_NE(m.joined().find("the disc's normal is the zero vector"), std::string::npos) << m.joined();
}

TEST(QuadricShapes, TorusAndSturm) {
  auto s = parse("#version 3.7;\ntorus { 2, 0.5 }\n");
  auto t = std::get<Torus>(only_object(s).shape);
  EXPECT_EQ(t.major, 2);
  EXPECT_EQ(t.minor, 0.5);
  EXPECT_FALSE(t.sturm);
  s = parse("#version 3.7;\ntorus { 2 0.5 sturm translate y }\n");
  EXPECT_TRUE(std::get<Torus>(only_object(s).shape).sturm);
  s = parse("#version 3.7;\n#declare T = torus { 2, 0.5 sturm }\nobject { T sturm off }\n");
  EXPECT_FALSE(std::get<Torus>(only_object(s).shape).sturm);
}

TEST(QuadricShapes, Refusals) {
  ParseError e = parse_error("#version 3.7;\ncylinder { <1,1,1>, <1,1,1>, 1 }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 1);
  EXPECT_NE(e.bare_message().find("degenerate cylinder"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\ncone { 0, 1, 0, 0.5 }\n");
  EXPECT_NE(e.bare_message().find("degenerate cone"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nsphere { 0, 1 sturm }\n");
  EXPECT_EQ(e.location().column, 15);
  EXPECT_NE(e.bare_message().find("keyword 'sturm' cannot be used with this object"), std::string::npos);
  e = parse_error("#version 3.7;\nunion { torus { 1, 0.2 } sphere { 0, 1 } sturm }\n");
  EXPECT_NE(e.bare_message().find("'sturm' cannot be used"), std::string::npos);
  e = parse_error("#version 3.7;\ncylinder { 0, y, 1 translate x open }\n");
  EXPECT_EQ(e.location().column, 32);
  EXPECT_NE(e.bare_message().find("'open' must directly follow"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nsphere { 0, 1 open }\n");
  EXPECT_NE(e.bare_message().find("'open'"), std::string::npos);
}

TEST(QuadricShapes, OvusTakesSturm) {   // as POV-Ray's STURM_OK_OBJECT, also on a copy of a declared one
  const SceneDescription s = parse("#version 3.7;\n#declare O = ovus { 1, 0.5 }\nobject { O sturm }\novus { 1, 0.5 }\n");
  EXPECT_TRUE(std::get<Ovus>(s.objects.at(0).shape).sturm);
  EXPECT_FALSE(std::get<Ovus>(s.objects.at(1).shape).sturm);
}

TEST(QuadricShapes, SturmOnAnUnrenderedShapeIsRefusedByName) {
  // A shape povtrace does not render yet (lemon) is refused by name, even when sturm follows it.
  const ParseError e = parse_error("#version 3.7;\n#declare O = lemon { 0, 1, y, 0.5, 1 }\nobject { O sturm }\n");
  EXPECT_NE(e.bare_message().find("the shape 'lemon'"), std::string::npos) << e.bare_message();
}

// inside() of a torus is answered by the renderer's geometry (ParseOptions::object_geometry); a parser without it refuses it.
TEST(QuadricShapes, InsideOfATorusNeedsTheRenderersGeometry) {
  const ParseError e = parse_error("#version 3.7;\n#declare T = torus { 1, 0.2 }\n#declare X = inside(T, 0);\n");
  EXPECT_NE(e.bare_message().find("the shape 'torus'"), std::string::npos) << e.bare_message();
}

}  // namespace
}  // namespace povtrace::test

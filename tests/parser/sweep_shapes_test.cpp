// lathe, prism and sor in the SDL: every form POV-Ray 3.7 accepts (spline and sweep keywords, optional commas,
// open, sturm, declared bodies), its point-count and point checks as located errors, and its prism closing rules.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Object& only_object(const SceneDescription& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return s.objects.at(0);
}

std::vector<ProfilePoint> points_of(const Profile& p) { return *p; }

void expect_error(const std::string& scene, int line, int column, const std::string& text) {
  const ParseError e = parse_error("#version 3.7;\n" + scene);
  EXPECT_EQ(e.location().line, line) << scene;
  EXPECT_EQ(e.location().column, column) << scene;
  EXPECT_NE(e.bare_message().find(text), std::string::npos) << e.bare_message();
}

TEST(SweepShapes, LatheSplinesPointsAndSturm) {
  auto s = parse("#version 3.7;\nlathe { 3, <0, 0> <1, 0.5>, <0, 1> translate x }\n");
  auto l = std::get<Lathe>(only_object(s).shape);
  EXPECT_EQ(l.spline, SplineKind::linear);   // the default
  EXPECT_FALSE(l.sturm);
  EXPECT_EQ(points_of(l.points), (std::vector<ProfilePoint>{{0, 0}, {1, 0.5}, {0, 1}}));
  EXPECT_EQ(only_object(s).world_from_object, Matrix::translation({1, 0, 0}));
  s = parse("#version 3.7;\nlathe { linear_spline bezier_spline 4.9, <0,0>, <1,0>, <1,1>, <0,1> sturm }\n");
  l = std::get<Lathe>(only_object(s).shape);
  EXPECT_EQ(l.spline, SplineKind::bezier);   // the last spline keyword wins; the count is truncated
  EXPECT_TRUE(l.sturm);
  EXPECT_EQ(l.points->size(), 4u);
  s = parse("#version 3.7;\nlathe { quadratic_spline 3, 0.5, <1, 1>, <0, 2> }\n");   // a float is <f, f>
  EXPECT_EQ(std::get<Lathe>(only_object(s).shape).points->front(), (ProfilePoint{0.5, 0.5}));
  s = parse("#version 3.7;\nlathe { cubic_spline 4, <-1, 0>, <1, 0>, <1, 1>, <-1, 1> sturm off }\n");
  EXPECT_FALSE(std::get<Lathe>(only_object(s).shape).sturm);   // end points may have x < 0
  s = parse("#version 3.7;\nlathe { bezier_spline 0 }\n");   // POV-Ray accepts an empty lathe
  EXPECT_TRUE(std::get<Lathe>(only_object(s).shape).points->empty());
  s = parse("#version 3.7;\n#declare L = lathe { 2, <1, 0>, <1, 1> }\nlathe { L scale 2 }\n");
  EXPECT_EQ(only_object(s).world_from_object, Matrix::scaling({2, 2, 2}));   // a declared body
}

TEST(SweepShapes, LatheErrors) {
  expect_error("lathe { 1, <0, 0> }\n", 2, 9, "linear splines must have at least 2 points");
  expect_error("lathe { quadratic_spline 2, <0, 0>, <1, 1> }\n", 2, 26, "at least 3 points");
  expect_error("lathe { cubic_spline 3, <0, 0>, <1, 1>, <0, 2> }\n", 2, 22, "at least 4 points");
  expect_error("lathe { bezier_spline 6 }\n", 2, 23, "four points per segment");
  expect_error("lathe { bezier_spline -4 }\n", 2, 23, "four points per segment");
  expect_error("lathe { 3, <0, 0>, <-0.5, 1>, <0, 2> }\n", 2, 20, "incorrect point in lathe");
  expect_error("lathe { 2, <0, 0>, <1, 1>, <2, 2> }\n", 2, 26, "'}'");   // more points than counted
  expect_error("lathe { 2, <0, 0, 0>, <1, 1> }\n", 2, 12, "expected a 2-D vector");
  expect_error("lathe { 2, <0, 0>, <1, 1> open }\n", 2, 27, "'open'");   // open is no lathe keyword
}

TEST(SweepShapes, PrismKeywordsHeightsAndOpen) {
  auto s = parse("#version 3.7;\nprism { conic_sweep quadratic_spline 1, 0.2, 6, <0,-1> <1,0> <0,1> <-1,0> <0,-1> "
                 "<1,0> open sturm }\n");
  auto p = std::get<Prism>(only_object(s).shape);
  EXPECT_EQ(p.spline, SplineKind::quadratic);
  EXPECT_TRUE(p.conic);
  EXPECT_EQ(p.height1, 0.2);   // sorted
  EXPECT_EQ(p.height2, 1);
  EXPECT_TRUE(p.open);
  EXPECT_TRUE(p.sturm);
  EXPECT_FALSE(p.degenerate);
  EXPECT_EQ(*p.segment_starts, (std::vector<std::uint32_t>{0, 1, 2, 3}));
  s = parse("#version 3.7;\nprism { linear_sweep 0, 1, 4, <0, 0>, <1, 0>, <0, 1>, <0, 0> }\n");
  p = std::get<Prism>(only_object(s).shape);
  EXPECT_FALSE(p.conic);
  EXPECT_FALSE(p.open);
  EXPECT_EQ(*p.segment_starts, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(SweepShapes, PrismSubOutlinesAndClosing) {
  // Two linear sub-outlines: the step from the first's closing point to the second's start is no segment.
  auto s = parse("#version 3.7;\nprism { 0, 1, 8, <0,0>, <3,0>, <0,3>, <0,0>, <1,1>, <2,1>, <1,2>, <1,1> }\n");
  EXPECT_EQ(*std::get<Prism>(only_object(s).shape).segment_starts, (std::vector<std::uint32_t>{0, 1, 2, 4, 5, 6}));
  // An unclosed linear outline is closed with a warning; other unclosed outlines are ignored with a warning.
  Messages m;
  s = parse("#version 3.7;\nprism { 0, 1, 3, <0, 0>, <1, 0>, <0, 1> }\n", &m);
  auto p = std::get<Prism>(only_object(s).shape);
  EXPECT_EQ(p.points->size(), 4u);
  EXPECT_EQ(p.points->back(), (ProfilePoint{0, 0}));
  EXPECT_NE(m.joined().find("test.pov:2:1: warning: linear prism not closed"), std::string::npos) << m.joined();
  m.items.clear();
  s = parse("#version 3.7;\nprism { bezier_spline 0, 1, 4, <0,0>, <1,0>, <1,1>, <0,1> }\n", &m);
  EXPECT_TRUE(std::get<Prism>(only_object(s).shape).degenerate);
  EXPECT_NE(m.joined().find("prism not closed"), std::string::npos) << m.joined();
  // Bézier sub-outlines: segments joined end to start, each run closing on itself.
  s = parse("#version 3.7;\nprism { bezier_spline 0, 1, 8, <0,0>, <1,0>, <1,1>, <0,1>, <0,1>, <-1,1>, <-1,0>, "
            "<0,0> }\n");
  p = std::get<Prism>(only_object(s).shape);
  EXPECT_FALSE(p.degenerate);
  EXPECT_EQ(*p.segment_starts, (std::vector<std::uint32_t>{0, 4}));
  // A cubic outline: one control point before and one after.
  s = parse("#version 3.7;\nprism { cubic_spline 0, 1, 6, <0,1>, <0,0>, <1,0>, <1,1>, <0,0>, <1,0> }\n");
  EXPECT_EQ(*std::get<Prism>(only_object(s).shape).segment_starts, (std::vector<std::uint32_t>{0, 1, 2}));
}

TEST(SweepShapes, PrismErrors) {
  expect_error("prism { 0, 1, 2, <0, 0>, <1, 0> }\n", 2, 15, "linear splines must have at least 3 points");
  expect_error("prism { quadratic_spline 0, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> }\n", 2, 32, "at least 5 points");
  expect_error("prism { cubic_spline 0, 1, 5, <0,0>, <1,0>, <0,1>, <0,0>, <1,0> }\n", 2, 28, "at least 6 points");
  expect_error("prism { bezier_spline 0, 1, 5 }\n", 2, 29, "four points per segment");
  // POV-Ray: "Prism not closed. Ignoring it.", then "Too few points in prism" when segments run past the end.
  expect_error("prism { quadratic_spline 0, 1, 6, <0,0>, <1,0>, <1,1>, <0,1>, <0,0>, <1,0.5> }\n", 2, 1,
               "too few points in prism");
}

TEST(SweepShapes, SorPointsOpenAndSturm) {
  auto s = parse("#version 3.7;\nsor { 4, <0, 0> <1, 0>, <1, 1>, <0, 1> open sturm rotate x*90 }\n");
  auto so = std::get<Sor>(only_object(s).shape);
  EXPECT_TRUE(so.open);
  EXPECT_TRUE(so.sturm);
  EXPECT_EQ(points_of(so.points), (std::vector<ProfilePoint>{{0, 0}, {1, 0}, {1, 1}, {0, 1}}));
  s = parse("#version 3.7;\nsor { 5, <1, 2>, <1, 0>, <1, 1>, <1, 2>, <1, -5> }\n");   // ends only set slopes
  so = std::get<Sor>(only_object(s).shape);
  EXPECT_FALSE(so.open);
  EXPECT_EQ(so.points->size(), 5u);
}

TEST(SweepShapes, SorErrors) {
  expect_error("sor { 3, <0, 0>, <1, 0>, <1, 1> }\n", 2, 7, "at least four points");
  expect_error("sor { 4, <0, 0>, <-1, 0>, <1, 1>, <0, 1> }\n", 2, 18, "incorrect point in surface of revolution");
  expect_error("sor { 5, <0, 0>, <1, 0.5>, <1, 1>, <0, 0.9>, <1, 2> }\n", 2, 36, "heights of points 2");
  // Compute_Sor: a segment's slope needs two different heights two points apart.
  expect_error("sor { 4, <0, 1>, <1, 0>, <1, 1>, <0, 2> }\n", 2, 26, "two before");
  expect_error("sor { 4, <0, 0>, <1, 0>, <1, 1>, <0, 1> open open }\n", 2, 46, "'open'");
}

TEST(SweepShapes, SturmOnlyWhereAllowed) {
  auto s = parse("#version 3.7;\n#declare L = lathe { 2, <0,0>, <1,1> }\nobject { L sturm }\n");
  EXPECT_TRUE(std::get<Lathe>(only_object(s).shape).sturm);
  s = parse("#version 3.7;\nprism { 0, 1, 4, <0,0>, <1,0>, <0,1>, <0,0> sturm 0 }\n");
  EXPECT_FALSE(std::get<Prism>(only_object(s).shape).sturm);
  expect_error("sphere { 0, 1 sturm }\n", 2, 15, "'sturm' cannot be used");
}

}  // namespace
}  // namespace povtrace::test

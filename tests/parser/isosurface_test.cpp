// isosurface in the SDL: the function (written or declared, internal ones included), every item POV-Ray 3.7 reads
// with its defaults and corrections, and the refusals (a function povtrace cannot evaluate, `evaluate`).
#include <gtest/gtest.h>

#include "parse_helpers.hpp"
#include "runtime/function_value.hpp"

namespace povtrace::test {
namespace {

const Isosurface& only_isosurface(const SceneDescription& s) {
  EXPECT_EQ(s.objects.size(), 1u);
  return std::get<Isosurface>(s.objects.at(0).shape);
}

double value_at(const Isosurface& iso, double x, double y, double z) {
  const double args[3] = {x, y, z};
  return sdl::evaluate_function(*iso.function, args, nullptr, 2);   // none of these functions reads noise
}

TEST(Isosurface, DefaultsAndTheFunction) {
  const auto s = parse("#version 3.7;\nisosurface { function { x*x + y - 2*z } }\n");
  const Isosurface& iso = only_isosurface(s);
  EXPECT_EQ(value_at(iso, 2, 1, 0.5), 4.0);
  EXPECT_FALSE(iso.sphere_container);
  EXPECT_EQ(iso.corner1, (Vec3{-1, -1, -1}));
  EXPECT_EQ(iso.corner2, (Vec3{1, 1, 1}));
  EXPECT_EQ(iso.threshold, 0);
  EXPECT_EQ(iso.accuracy, 0.001);
  EXPECT_EQ(iso.max_gradient, 1.1);
  EXPECT_EQ(iso.max_trace, 1);
  EXPECT_FALSE(iso.open);
}

TEST(Isosurface, ItemsInAnyOrder) {
  auto s = parse("#version 3.7;\n#declare F = function(a, b, c) { a + b + c }\n"
                 "isosurface { function { F(x, y, z) - 1 } open max_gradient 3 threshold 0.5 accuracy 0.01\n"
                 "  contained_by { box { <2, 1, 0>, <-1, -1, 3> } } max_trace 4.9 translate x }\n");
  const Isosurface& iso = only_isosurface(s);
  EXPECT_EQ(value_at(iso, 1, 1, 1), 2.0);
  EXPECT_TRUE(iso.open);
  EXPECT_EQ(iso.max_gradient, 3);
  EXPECT_EQ(iso.threshold, 0.5);
  EXPECT_EQ(iso.accuracy, 0.01);
  EXPECT_EQ(iso.corner1, (Vec3{-1, -1, 0}));   // sorted per axis
  EXPECT_EQ(iso.corner2, (Vec3{2, 1, 3}));
  EXPECT_EQ(iso.max_trace, 4);
  EXPECT_EQ(s.objects[0].world_from_object, Matrix::translation({1, 0, 0}));
  s = parse("#version 3.7;\n#include \"functions.inc\"\nisosurface { function { f_sphere(x, y, z, 0.5) } "
            "contained_by { sphere { <0, 1, 0>, 2 } } all_intersections }\n");
  const Isosurface& iso2 = only_isosurface(s);
  EXPECT_TRUE(iso2.sphere_container);
  EXPECT_EQ(iso2.centre, (Vec3{0, 1, 0}));
  EXPECT_EQ(iso2.radius, 2);
  EXPECT_EQ(iso2.max_trace, 10);
  EXPECT_NEAR(value_at(iso2, 1, 0, 0), 0.5, 1e-15);
  s = parse("#version 3.7;\nisosurface { function { x } contained_by { } }\n");   // an empty block: the default
  EXPECT_EQ(only_isosurface(s).corner2, (Vec3{1, 1, 1}));
}

TEST(Isosurface, OutOfRangeValuesAreCorrectedWithWarnings) {
  Messages m;
  const auto s = parse("#version 3.7;\nisosurface { function { x } accuracy 0 max_gradient -1 max_trace 20 }\n", &m);
  const Isosurface& iso = only_isosurface(s);
  EXPECT_EQ(iso.accuracy, 0.001);
  EXPECT_EQ(iso.max_gradient, 1.1);
  EXPECT_EQ(iso.max_trace, 10);
  EXPECT_NE(m.joined().find("test.pov:2:1: warning: isosurface 'accuracy' is not positive"), std::string::npos);
  EXPECT_NE(m.joined().find("'max_gradient' is not positive"), std::string::npos);
  EXPECT_NE(m.joined().find("'max_trace' exceeds the maximum of 10"), std::string::npos);
  m.items.clear();
  EXPECT_EQ(only_isosurface(parse("#version 3.7;\nisosurface { function { x } max_trace 0 }\n", &m)).max_trace, 1);
  EXPECT_NE(m.joined().find("'max_trace' is not positive"), std::string::npos);
}

TEST(Isosurface, Errors) {
  ParseError e = parse_error("#version 3.7;\nisosurface { threshold 1 function { x } }\n");
  EXPECT_EQ(e.location().column, 14);
  EXPECT_NE(e.bare_message().find("'function' starting the isosurface"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nisosurface { function { x } contained_by { cone { 0, 1, y, 0 } } }\n");
  EXPECT_EQ(e.location().column, 44);
  EXPECT_NE(e.bare_message().find("closing contained_by"), std::string::npos) << e.bare_message();
  e = parse_error("#version 3.7;\nisosurface { function(a) { a } }\n");
  EXPECT_NE(e.bare_message().find("a float function of x, y and z"), std::string::npos) << e.bare_message();
}

TEST(Isosurface, EvaluateTakesThreeNumbers) {
  const SceneDescription sd = parse("#version 3.7;\nisosurface { function { x } evaluate 1, 2 0.9 max_gradient 3 }\n");
  const auto& iso = std::get<Isosurface>(sd.objects.at(0).shape);
  EXPECT_FALSE(sd.objects.at(0).unsupported);
  EXPECT_TRUE(iso.evaluate);
  EXPECT_EQ(iso.evaluate_params, (std::array<double, 3>{1, 2, 0.9}));   // the comma is optional, as in POV-Ray
  EXPECT_EQ(iso.max_gradient, 3.0);
  const ParseError e = parse_error("#version 3.7;\nisosurface { function { x } evaluate 1, 2 }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 43);
  EXPECT_NE(e.bare_message().find("found '}'"), std::string::npos) << e.bare_message();
}

}  // namespace
}  // namespace povtrace::test

// Expressions (povray-sdl-and-geometry.md §5): precedence, the two levels, term counts and promotion, component
// selection, built-in functions, random numbers, string functions and colour forms. Expected values are POV-Ray
// 3.7's own output (semantics-scenes/sdl_expr.pov, sdl_lex.pov, or checked with `povray` for this test).
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

// ---- Float expressions ----------------------------------------------------------------------------------------
struct FloatCase {
  std::string expr;
  double expected;
};

class FloatExpression : public ::testing::TestWithParam<FloatCase> {};

TEST_P(FloatExpression, Evaluates) {
  EXPECT_NEAR(eval_float(GetParam().expr), GetParam().expected, 1e-9) << GetParam().expr;
}

INSTANTIATE_TEST_SUITE_P(
    Precedence, FloatExpression,
    ::testing::Values(FloatCase{"1+2*3", 7}, FloatCase{"(1+2)*3", 9}, FloatCase{"-2*3", -6},
                      FloatCase{"10-4-3", 3},    // left-associative
                      FloatCase{"8/4/2", 1}, FloatCase{"-<1,2,3>.y", -2},   // unary minus takes the postfix
                      FloatCase{"--3", 3}, FloatCase{"+3", 3}, FloatCase{"2*-3", -6}, FloatCase{"!0", 1},
                      FloatCase{"!5", 0}, FloatCase{"!1e-11", 1}));

INSTANTIATE_TEST_SUITE_P(
    FullLevel, FloatExpression,
    ::testing::Values(
        FloatCase{"(1<2)", 1}, FloatCase{"(2<1)", 0}, FloatCase{"(1=1)", 1}, FloatCase{"(1!=1)", 0},
        FloatCase{"(2>=2)", 1}, FloatCase{"(1<2<1)", 0},   // chained left to right: (1<2)<1
        // & and | share one level and associate left: (1 | 0) & 0.
        FloatCase{"(1 | 0 & 0)", 0}, FloatCase{"(0 & 0 | 1)", 1}, FloatCase{"(0 | 1)", 1}, FloatCase{"(1 & 0)", 0},
        FloatCase{"(1 ? 2 : 3)", 2}, FloatCase{"(0 ? 2 : 3)", 3}, FloatCase{"(1+1 < 3 ? 10 : 20)", 10},
        FloatCase{"(0 ? 1 : 0 ? 2 : 3)", 3}, FloatCase{"(1e-11 ? 2 : 3)", 3},   // true iff |c| > 1e-10
        // = and != compare with a 1e-10 tolerance; < and > are exact; <= and >= are "strict or eps-equal".
        FloatCase{"(1 = 1+1e-11)", 1}, FloatCase{"(1 = 1+1e-9)", 0}, FloatCase{"(1 != 1+1e-11)", 0},
        FloatCase{"(1 < 1+1e-11)", 1}, FloatCase{"(1+1e-11 <= 1)", 1}, FloatCase{"(1 >= 1+1e-11)", 1},
        FloatCase{"(1+1e-9 <= 1)", 0},
        // Comparisons inside single-argument function calls are at the full level too.
        FloatCase{"abs(1 < 2)", 1}, FloatCase{"1 + (2 > 1)", 2}));

INSTANTIATE_TEST_SUITE_P(
    Functions, FloatExpression,
    ::testing::Values(
        FloatCase{"abs(-2.5)", 2.5}, FloatCase{"sqrt(16)", 4}, FloatCase{"pow(2,10)", 1024},
        FloatCase{"min(4,2,8)", 2}, FloatCase{"max(1,5,3)", 5}, FloatCase{"min(7)", 7},
        FloatCase{"mod(-7,3)", -1}, FloatCase{"mod(7,-3)", 1}, FloatCase{"mod(7.5,2)", 1.5},
        FloatCase{"int(-2.5)", -2}, FloatCase{"int(2.9)", 2}, FloatCase{"div(-7,2)", -3}, FloatCase{"div(7,2)", 3},
        FloatCase{"floor(-2.5)", -3}, FloatCase{"ceil(-2.5)", -2}, FloatCase{"select(-1,10,20)", 10},
        FloatCase{"select(0,10,20)", 20}, FloatCase{"select(-1,10,20,30)", 10}, FloatCase{"select(0,10,20,30)", 20},
        FloatCase{"select(1,10,20,30)", 30}, FloatCase{"log(100)", 2}, FloatCase{"ln(exp(1))", 1},
        FloatCase{"atan2(1,0)", M_PI / 2}, FloatCase{"degrees(pi)", 180}, FloatCase{"radians(180)", M_PI},
        FloatCase{"sin(pi/2)", 1}, FloatCase{"cos(0)", 1}, FloatCase{"vlength(<3,4,0>)", 5},
        FloatCase{"vlength(<1,2>)", std::sqrt(5.0)},   // a 2-D vector is zero-padded where a vector is needed
        FloatCase{"vdot(x,y)", 0}, FloatCase{"vdot(<1,2,3>,<4,5,6>)", 32}, FloatCase{"bitwise_and(12,10)", 8},
        FloatCase{"bitwise_or(12,10)", 14}, FloatCase{"bitwise_xor(12,10)", 6}, FloatCase{"strlen(\"a\\nb\")", 3},
        FloatCase{"strcmp(\"abc\",\"abd\")", -1}, FloatCase{"asc(\"A\")", 65}, FloatCase{"val(\"12.5x\")", 12.5},
        FloatCase{"true+yes+on", 3}, FloatCase{"false+no+off", 0}, FloatCase{"clock", 0},
        FloatCase{"image_width", 800}, FloatCase{"image_height", 600}, FloatCase{"version", 3.7}));

INSTANTIATE_TEST_SUITE_P(
    Components, FloatExpression,
    ::testing::Values(FloatCase{"<1,2,3>.x", 1}, FloatCase{"<1,2,3>.z", 3}, FloatCase{"<1,2,3>.red", 1},
                      FloatCase{"<1,2,3>.green", 2}, FloatCase{"<1,2,3>.blue", 3}, FloatCase{"<5,6>.u", 5},
                      FloatCase{"<5,6>.v", 6}, FloatCase{"<1,2,3,4>.t", 4}, FloatCase{"(x+y*2).y", 2}));

TEST(Expressions, DeclaredValuesKeepTheirComponents) {
  const std::string prelude =
      "#declare V = <1,2,3>; #declare C1 = rgb <1,0.5,0.25>; #declare C2 = rgbf <1,0.5,0.25,0.1>;"
      "#declare C3 = rgbt <1,0.5,0.25,0.1>;";
  EXPECT_NEAR(eval_float("V.x + 10*V.z", prelude), 31, 1e-12);
  EXPECT_NEAR(eval_float("C1.gray", prelude), 0.62, 1e-12);   // 0.297 R + 0.589 G + 0.114 B
  // Declared colours are stored in single precision, as POV-Ray does (0.1 reads back as 0.100000001490).
  // (eval_float reads values back through a 9-decimal #debug print: 1e-9 is its resolution, finer than the
  // 1.5e-9 between 0.1 and its float.)
  EXPECT_NEAR(eval_float("C2.filter", prelude), static_cast<float>(0.1), 1e-9);
  EXPECT_NEAR(eval_float("C3.transmit", prelude), static_cast<float>(0.1), 1e-9);
  EXPECT_NEAR(eval_float("C3.filter", prelude), 0, 1e-12);
  EXPECT_NEAR(eval_float("C1.x", prelude), 1, 1e-12);
}

TEST(Expressions, DivisionByZeroGivesInfinity) {
  EXPECT_EQ(eval_float("1/0"), std::numeric_limits<double>::infinity());
}

// ---- Vector expressions and promotion ---------------------------------------------------------------------------
struct TermsCase {
  std::string expr;
  std::vector<double> expected;   // five terms (vstr(5, ...))
};

class Terms : public ::testing::TestWithParam<TermsCase> {};

TEST_P(Terms, Evaluates) {
  const auto got = eval_terms(GetParam().expr);
  ASSERT_EQ(got.size(), 5u) << GetParam().expr;
  // A colour result is stored in single precision (POV-Ray's colour type); other values stay double.
  const bool colour = GetParam().expr.find("rgb") != std::string::npos || GetParam().expr.find("colo") != std::string::npos;
  for (std::size_t i = 0; i < 5; ++i) {
    const double want = colour ? static_cast<float>(GetParam().expected[i]) : GetParam().expected[i];
    EXPECT_NEAR(got[i], want, 1e-9) << GetParam().expr << " term " << i;   // 9-decimal print resolution
  }
}

INSTANTIATE_TEST_SUITE_P(
    Promotion, Terms,
    ::testing::Values(TermsCase{"<1,2>", {1, 2, 0, 0, 0}}, TermsCase{"<1,2> + <1,2,3>", {2, 4, 3, 0, 0}},
                      TermsCase{"x+1", {2, 1, 1, 0, 0}},   // a float is broadcast to every term
                      TermsCase{"2*x", {2, 0, 0, 0, 0}}, TermsCase{"<1,2,3>*<2,2,2>", {2, 4, 6, 0, 0}},
                      TermsCase{"<2,4,6>/2", {1, 2, 3, 0, 0}}, TermsCase{"0+t", {0, 0, 0, 1, 0}},
                      TermsCase{"u", {1, 0, 0, 0, 0}}, TermsCase{"v", {0, 1, 0, 0, 0}},
                      TermsCase{"<1, 2, 3 -1>", {1, 2, 2, 0, 0}},   // commas are optional: 3-1 is one term
                      TermsCase{"<1 2 3>", {1, 2, 3, 0, 0}}, TermsCase{"-<1,2,3>", {-1, -2, -3, 0, 0}}));

INSTANTIATE_TEST_SUITE_P(
    VectorFunctions, Terms,
    ::testing::Values(TermsCase{"vcross(x,y)", {0, 0, 1, 0, 0}}, TermsCase{"vnormalize(<3,0,4>)", {0.6, 0, 0.8, 0, 0}},
                      TermsCase{"vrotate(x,<0,90,0>)", {0, 0, -1, 0, 0}},
                      TermsCase{"vrotate(y,<90,0,0>)", {0, 0, 1, 0, 0}},
                      TermsCase{"vrotate(x,<0,0,90>)", {0, 1, 0, 0, 0}},
                      TermsCase{"vrotate(y,<90,0,90>)", {0, 0, 1, 0, 0}},   // about x first, then z
                      TermsCase{"vaxis_rotate(x,y,90)", {0, 0, -1, 0, 0}},   // same sense as rotate
                      TermsCase{"vaxis_rotate(x,<0,2,0>,90)", {0, 0, -1, 0, 0}},   // the axis is normalised
                      TermsCase{"vaxis_rotate(y,x,90)", {0, 0, 1, 0, 0}}));

// ---- Colours -------------------------------------------------------------------------------------------------
INSTANTIATE_TEST_SUITE_P(
    Colours, Terms,
    ::testing::Values(
        TermsCase{"rgb <1,0.5,0.25>", {1, 0.5, 0.25, 0, 0}}, TermsCase{"rgb 0.5", {0.5, 0.5, 0.5, 0, 0}},
        TermsCase{"rgbf 1", {1, 1, 1, 1, 0}}, TermsCase{"rgbt <1,0,0,.5>", {1, 0, 0, 0, 0.5}},
        TermsCase{"rgbf <1,0.5,0.25,0.1>", {1, 0.5, 0.25, 0.1, 0}},
        TermsCase{"rgbft <1,0.5,0.25,0.1,0.2>", {1, 0.5, 0.25, 0.1, 0.2}},
        TermsCase{"color red 1 green .5", {1, 0.5, 0, 0, 0}}, TermsCase{"colour blue 1", {0, 0, 1, 0, 0}},
        TermsCase{"rgb <1,0,0> filter 0.5", {1, 0, 0, 0.5, 0}}, TermsCase{"rgb x", {1, 0, 0, 0, 0}},
        TermsCase{"color <1,0,1>", {1, 0, 1, 0, 0}},
        TermsCase{"color 0.5", {0.5, 0.5, 0.5, 0.5, 0.5}},   // a bare float fills all five channels
        TermsCase{"rgb <1,0.5,0.25>*2", {2, 1, 0.5, 0, 0}},   // a full expression after rgb
        TermsCase{"rgb (1 < 2)", {1, 1, 1, 0, 0}}, TermsCase{"rgb 1 < 2", {1, 1, 1, 0, 0}},
        TermsCase{"rgbft <1,1,1,1,1>*0.5", {0.5, 0.5, 0.5, 0.5, 0.5}}));

TEST(Expressions, ColourArithmeticActsOnAllFiveChannels) {
  const std::string prelude =
      "#declare C1 = rgb <1,0.5,0.25>; #declare C2 = rgbf <1,0.5,0.25,0.1>;"
      "#declare W = rgbft <1,1,1,0.4,0.2>;";
  auto near = [](const std::vector<double>& got, const std::vector<double>& want) {
    ASSERT_EQ(got.size(), want.size());
    // Operands are stored colours (single precision); the result is stored as a colour again.
    for (std::size_t i = 0; i < want.size(); ++i)
      EXPECT_NEAR(got[i], static_cast<float>(want[i]), 1e-9) << "term " << i;   // 9-decimal print resolution
  };
  near(eval_terms("C1*0.5", prelude), {0.5, 0.25, 0.125, 0, 0});
  near(eval_terms("C1+C2", prelude), {2, 1, 0.5, 0.1, 0});
  near(eval_terms("W*0.5", prelude), {0.5, 0.5, 0.5, 0.2, 0.1});
  near(eval_terms("color C1 transmit 0.3", prelude), {1, 0.5, 0.25, 0, 0.3});
  near(eval_terms("color W red 0", prelude), {0, 1, 1, 0.4, 0.2});
}

// ---- Random numbers ---------------------------------------------------------------------------------------------
TEST(Expressions, SeedAndRandReproducePovRaysSequence) {
  const std::string out = debug_output(
      "#version 3.7;\n#declare S = seed(42);\n"
      "#debug concat(str(rand(S),0,6), \" \", str(rand(S),0,6), \" \", str(rand(S),0,6), \"\\n\")\n"
      "#declare S0 = seed(0);\n#debug concat(str(rand(S0),0,6), \"\\n\")\n");
  EXPECT_EQ(out, "0.723583 0.329979 0.755762\n0.000003\n");
}

TEST(Expressions, RandomStreamsAreIndependent) {
  const std::string out = debug_output(
      "#version 3.7;\n#declare A = seed(42); #declare B = seed(42);\n"
      "#declare A1 = rand(A); #declare A2 = rand(A); #declare B1 = rand(B);\n"
      "#debug concat(str(A1,0,6), \" \", str(A2,0,6), \" \", str(B1,0,6))\n");
  EXPECT_EQ(out, "0.723583 0.329979 0.723583");
}

// ---- String functions -----------------------------------------------------------------------------------------
struct StringCase {
  std::string expr;
  std::string expected;
};

class StringExpression : public ::testing::TestWithParam<StringCase> {};

TEST_P(StringExpression, Evaluates) {
  EXPECT_EQ(debug_output("#version 3.7;\n#debug " + GetParam().expr + "\n"), GetParam().expected)
      << GetParam().expr;
}

INSTANTIATE_TEST_SUITE_P(
    Table, StringExpression,
    ::testing::Values(StringCase{"str(2,-5,1)", "002.0"}, StringCase{"str(2,5,0)", "    2"},
                      StringCase{"str(3.14159,0,-1)", "3.141590"}, StringCase{"str(-1.5,0,2)", "-1.50"},
                      StringCase{"concat(\"a\", \"b\", str(1,0,0))", "ab1"},
                      StringCase{"substr(\"abcdef\",2,3)", "bcd"}, StringCase{"chr(65)", "A"},
                      StringCase{"strupr(\"aB\")", "AB"}, StringCase{"strlwr(\"aB\")", "ab"},
                      StringCase{"vstr(3, <1,2,3>, \", \", 0, 1)", "1.0, 2.0, 3.0"},
                      StringCase{"vstr(2, <1,2,3>, \"/\", 0, 0)", "1/2"}));

// ---- Promotion where a vector is required, seen through a scene ---------------------------------------------
void expect_matrix_near(const Matrix& a, const Matrix& b) {
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 3; ++j)
      EXPECT_NEAR(a.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)],
                  b.m[static_cast<std::size_t>(i)][static_cast<std::size_t>(j)], 1e-12)
          << "row " << i << " column " << j;
}

TEST(Expressions, FloatsBroadcastWhereAVectorIsRequired) {
  const SceneDescription s = parse(
      "#version 3.7;\n"
      "sphere { 0, 1 rotate 90 }\n sphere { 0, 1 rotate <90,90,90> }\n"
      "sphere { 0, 1 scale 2 translate 1 }\n sphere { 1, .5 }\n");
  ASSERT_EQ(s.objects.size(), 4u);
  expect_matrix_near(s.objects[0].world_from_object, s.objects[1].world_from_object);
  expect_matrix_near(s.objects[2].world_from_object,
                     Matrix::scaling({2, 2, 2}) * Matrix::translation({1, 1, 1}));
  const auto& sphere = std::get<Sphere>(s.objects[3].shape);
  EXPECT_EQ(sphere.centre, (Vec3{1, 1, 1}));
  EXPECT_EQ(sphere.radius, 0.5);
}

TEST(Expressions, VectorsInParametersAreAdditiveLevel) {
  // `<1,2,3> - 1` is one vector parameter; the comma before the radius is optional (POV-Ray's Parse_Comma).
  const SceneDescription s = parse("#version 3.7;\nsphere { <1,2,3> - 1, 2 }\nsphere { <0,0,0> 3 }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).centre, (Vec3{0, 1, 2}));
  EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).radius, 2);
  EXPECT_EQ(std::get<Sphere>(s.objects[1].shape).radius, 3);
}

// ---- Expression errors -----------------------------------------------------------------------------------------
struct ExprError {
  std::string text;
  int line, column;
  std::string fragment;
};

class ExpressionErrors : public ::testing::TestWithParam<ExprError> {};

TEST_P(ExpressionErrors, PositionAndMessage) {
  const ParseError e = parse_error(GetParam().text);
  EXPECT_EQ(e.location().line, GetParam().line) << e.what();
  EXPECT_EQ(e.location().column, GetParam().column) << e.what();
  EXPECT_NE(e.bare_message().find(GetParam().fragment), std::string::npos) << e.bare_message();
}

INSTANTIATE_TEST_SUITE_P(
    Table, ExpressionErrors,
    ::testing::Values(
        // Comparisons exist only at the full level: after `1` the #declare wants its ';' (povray: the
        // "require semi-colon" error).
        ExprError{"#version 3.7;\n#declare B = 1 < 2;\n", 2, 16, "expected ';' after the value of B, found '<'"},
        ExprError{"#version 3.7;\n#declare B = <1,2,3>.w;\n", 2, 22, "a component name"},
        ExprError{"#version 3.7;\n#declare B = <1,2>.z;\n", 2, 20, "'.z' selects a component"},
        ExprError{"#version 3.7;\n#declare B = sqrt(-1);\n", 2, 14, "sqrt of a negative number"},
        ExprError{"#version 3.7;\n#declare B = mod(1,0);\n", 2, 14, "mod by zero"},
        ExprError{"#version 3.7;\n#declare B = pow(0,0);\n", 2, 14, "pow(0, 0)"},
        ExprError{"#version 3.7;\n#declare B = abs(1,2);\n", 2, 19, "',' or ')'"},
        ExprError{"#version 3.7;\n#declare B = sqr(3);\n", 2, 14, "unsupported"},
        ExprError{"#version 3.7;\n#declare B = sin(x);\n", 2, 18, "expected a float, found a vector"},
        ExprError{"#version 3.7;\n#declare B = substr(\"abc\",3,2);\n", 2, 14, "out of range"},
        ExprError{"#version 3.7;\n#declare B = (1 ? 2);\n", 2, 20, "expected ':'"},
        ExprError{"#version 3.7;\n#declare B = 1 + ;\n", 2, 18, "expected a number, vector or expression"},
        ExprError{"#version 3.7;\n#declare B = rand(0);\n", 2, 14, "seed() did not create"}));

}  // namespace
}  // namespace povtrace::test

// SDL spline values: `spline { … }` declarations, calls S(t) and S(t, type), copies, `function { spline { … } }`,
// and the errors of malformed ones. Every expected value below was printed by POV-Ray 3.7.0.10 (the `povray`
// binary, `#debug vstr(…, S(t), …, 0, 15)`), on the same scene text.
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

// Four entries, unevenly spaced, shared by the interpolation tests (POV-Ray: base.pov).
const std::string kEntries = "0, <0,0,0> 1, <1,2,0> 3, <2,-1,4> 4, <0,0,1>";

std::string spline_of_type(const std::string& type) {
  return "#declare S = spline { " + type + " " + kEntries + " }\n";
}

void expect_vector(const std::string& call, const std::string& prelude, std::vector<double> expected) {
  const std::vector<double> got = eval_terms(call, prelude);
  expected.resize(5, 0.0);
  ASSERT_EQ(got.size(), 5u) << call;
  for (std::size_t i = 0; i < 5; ++i) EXPECT_NEAR(got[i], expected[i], 1e-9) << call << " term " << i;
}

void expect_error(const std::string& scene, int line, int column, const std::string& text) {
  const ParseError e = parse_error("#version 3.7;\n" + scene);
  EXPECT_EQ(e.location().line, line) << scene;
  EXPECT_EQ(e.location().column, column) << scene;
  EXPECT_NE(e.bare_message().find(text), std::string::npos) << e.bare_message();
}

TEST(Spline, LinearHoldsTheEndValuesOutsideItsRange) {
  const std::string s = spline_of_type("linear_spline");
  expect_vector("S(-1)", s, {0, 0, 0});
  expect_vector("S(0)", s, {0, 0, 0});
  expect_vector("S(0.3)", s, {0.3, 0.6, 0});
  expect_vector("S(1)", s, {1, 2, 0});
  expect_vector("S(1.5)", s, {1.25, 1.25, 1});
  expect_vector("S(2.2)", s, {1.6, 0.2, 2.4});
  expect_vector("S(3.7)", s, {0.6, -0.3, 1.9});
  expect_vector("S(5)", s, {0, 0, 1});
  // linear is the default type
  expect_vector("S(1.5)", "#declare S = spline { " + kEntries + " }\n", {1.25, 1.25, 1});
}

TEST(Spline, QuadraticUsesThePreviousEntryExceptOnTheFirstSegment) {
  const std::string s = spline_of_type("quadratic_spline");
  expect_vector("S(-1)", s, {0, 0, 0});
  expect_vector("S(0.3)", s, {0.335, 0.845, -0.14});
  expect_vector("S(1)", s, {1, 2, 0});
  expect_vector("S(1.5)", s, {1.375, 2.125, 0.5});
  expect_vector("S(2.2)", s, {1.76, 1.32, 1.76});
  expect_vector("S(3)", s, {2, -1, 4});
  expect_vector("S(3.7)", s, {0.775, -0.475, 2.25});
  expect_vector("S(5)", s, {0, 0, 1});
}

TEST(Spline, CubicIsCatmullRomHeldAtTheSecondAndNextToLastEntries) {
  const std::string s = spline_of_type("cubic_spline");
  expect_vector("S(-1)", s, {1, 2, 0});
  expect_vector("S(0)", s, {1, 2, 0});
  expect_vector("S(0.3)", s, {1, 2, 0});
  expect_vector("S(1)", s, {1, 2, 0});
  expect_vector("S(1.5)", s, {1.4375, 1.625, 0.953125});
  expect_vector("S(2.2)", s, {2.008, 0.176, 2.928});
  expect_vector("S(3)", s, {2, -1, 4});
  expect_vector("S(3.7)", s, {2, -1, 4});
  expect_vector("S(5)", s, {2, -1, 4});
}

TEST(Spline, NaturalHasZeroCurvatureAtItsEnds) {
  const std::string s = spline_of_type("natural_spline");
  expect_vector("S(-1)", s, {0, 0, 0});
  expect_vector("S(0.3)", s, {0.2829375, 0.8218125, -0.1876875});
  expect_vector("S(1)", s, {1, 2, 0});
  expect_vector("S(1.5)", s, {1.578125, 1.671875, 1.09375});
  expect_vector("S(2.2)", s, {2.188, 0.236, 3.108});
  expect_vector("S(3)", s, {2, -1, 4});
  expect_vector("S(3.7)", s, {0.7194375, -0.4876875, 2.1900625});
  expect_vector("S(5)", s, {0, 0, 1});
}

TEST(Spline, TheCallsSecondArgumentChoosesTheType) {
  const std::string s = spline_of_type("linear_spline");
  expect_vector("S(0.3, natural_spline)", s, {0.2829375, 0.8218125, -0.1876875});
  expect_vector("S(3.7, natural_spline)", s, {0.7194375, -0.4876875, 2.1900625});
  expect_vector("S(2.2, cubic_spline)", s, {2.008, 0.176, 2.928});
  expect_vector("S(1.5, quadratic_spline)", s, {1.375, 2.125, 0.5});
  expect_vector("S(1.5)", s, {1.25, 1.25, 1});   // the spline itself is unchanged
}

TEST(Spline, TooFewEntriesFallBackAsInPovRay) {
  const std::string two = "0, <0,0,0> 2, <2,4,6>";
  for (const char* t : {"quadratic_spline", "natural_spline"}) {   // a line between the two
    const std::string s = "#declare S = spline { " + std::string(t) + " " + two + " }\n";
    expect_vector("S(-1)", s, {0, 0, 0});
    expect_vector("S(0.3)", s, {0.3, 0.6, 0.9});
    expect_vector("S(1.5)", s, {1.5, 3, 4.5});
    expect_vector("S(5)", s, {2, 4, 6});
  }
  const std::string cubic2 = "#declare S = spline { cubic_spline " + two + " }\n";   // their mean everywhere
  for (const char* t : {"S(-1)", "S(0.3)", "S(2.2)"}) expect_vector(t, cubic2, {1, 2, 3});
  // three entries: the cubic spline is its middle entry everywhere
  const std::string cubic3 = "#declare S = spline { cubic_spline 0, <0,0,0> 1, <1,1,1> 2, <2,4,6> }\n";
  for (const char* t : {"S(-1)", "S(0.3)", "S(1.5)", "S(5)"}) expect_vector(t, cubic3, {1, 1, 1});
  const std::string one = "#declare S = spline { natural_spline 1, <7,8,9> }\n";   // one entry: its value
  for (const char* t : {"S(-1)", "S(1)", "S(3.7)"}) expect_vector(t, one, {7, 8, 9});
}

TEST(Spline, EntriesAreSortedAndARepeatedTReplacesAllButTheLast) {
  expect_vector("S(1.5)", "#declare S = spline { 3, <3,3,3>, 1, <1,1,1>, 2, <2,2,2> }\n", {1.5, 1.5, 1.5});
  // POV-Ray 3.7 loses a second value for the largest t (2 here) but replaces the others.
  const std::string d =
      "#declare S = spline { 0, <0,0,0> 1, <1,1,1> 2, <2,2,2> 1, <5,5,5> 0, <-1,-1,-1> 2, <9,9,9> }\n";
  expect_vector("S(0)", d, {-1, -1, -1});
  expect_vector("S(1)", d, {5, 5, 5});
  expect_vector("S(2)", d, {2, 2, 2});
  expect_vector("S(1.5)", d, {3.5, 3.5, 3.5});
}

TEST(Spline, TermsAreTheLargestGivenAndAFloatIsAUvPair) {
  const std::string f = "#declare S = spline { 0, 1 1, 3 }\n";
  expect_vector("S(0.5)", f, {2, 2});
  expect_vector("S(0.5) + <0,0,7>", f, {2, 2, 7});   // two terms: promoted with a zero z
  const std::string mixed = "#declare S = spline { 0, 5 1, <1,2,3> }\n";
  expect_vector("S(0)", mixed, {5, 5, 0});
  expect_vector("S(0.5)", mixed, {3, 3.5, 1.5});
  expect_vector("S(0.5)", "#declare S = spline { 0, <1,2,3,4> 1, <2,3,4,5> }\n", {1.5, 2.5, 3.5, 4.5});
  expect_vector("S(0.5)", "#declare S = spline { 0, <1,2,3,4,5> 1, <2,3,4,5,6> }\n", {1.5, 2.5, 3.5, 4.5, 5.5});
  EXPECT_NEAR(eval_float("V.u", "#declare S = spline { 0, <1,2> 1, <3,4> }\n#declare V = S(0.5);"), 2, 1e-12);
}

TEST(Spline, CommasAreOptionalAndTypeKeywordsRepeat) {
  expect_vector("S(1.5)", "#declare S = spline { 0 <1,2,3> 1 <3,4,5> 2, <5,6,7>, }\n", {4, 5, 6});
  expect_vector("S(0.5)", "#declare S = spline { cubic_spline linear_spline 0, <0,0,0> 1, <1,1,1> }\n",
                {0.5, 0.5, 0.5});
}

TEST(Spline, CopiesAddEntriesOrChangeTheType) {
  const std::string u = "#declare U = spline { 3, <3,3,3>, 1, <1,1,1>, 2, <2,2,2> }\n";
  expect_vector("C(3.5)", u + "#declare C = spline { U 4, <0,0,0> }\n", {1.5, 1.5, 1.5});
  expect_vector("U(3.5)", u + "#declare C = spline { U 4, <0,0,0> }\n", {3, 3, 3});   // U unchanged
  expect_vector("C(1.5)", u + "#declare C = spline { U quadratic_spline }\n", {1.5, 1.5, 1.5});
  expect_vector("C(1.5)", u + "#declare C = U;\n", {1.5, 1.5, 1.5});
  expect_vector("V", u + "#declare V = U(1.5);\n", {1.5, 1.5, 1.5});
}

TEST(Spline, EntriesMayComeFromLoopsAndExpressions) {
  const std::string s =
      "#declare S = spline { natural_spline #for (I, 0, 3) I, <I, I*I, -I> #end }\n";
  expect_vector("S(1.5)", s, {1.5, 2.2, -1.5});   // natural: the parabola bends less near the free ends
  expect_vector("S(0.5)*2 + y", "#declare S = spline { 0, x 1, 3*x }\n", {4, 1, 0});
}

TEST(Spline, MacrosArraysAndLoopsHoldAndCallSplines) {
  // POV-Ray 3.7.0.10 printed these lines for the same scene (loop2.pov), the -0 included: a natural spline
  // summed in POV-Ray's order reproduces the sign of a zero at a knot.
  const std::string out = debug_output(
      "#version 3.7;\n"
      "#declare S = spline { cubic_spline -1, <0,0,0> 0, <1,0,0> 1, <1,1,0> 2, <0,1,1> 3, <0,0,2> }\n"
      "#for (I, 0, 1, 0.5)\n"
      "  #debug concat(vstr(3, S(I), \",\", 0, 6), \" \", vstr(3, S(I, natural_spline) + x, \",\", 0, 6), \"\\n\")\n"
      "#end\n"
      "#macro Make(A) spline { linear_spline 0, <A,0,0> 1, <0,A,0> } #end\n"
      "#macro Local() #local L = spline { 0, 1 2, 5 } L #end\n"
      "#declare M = Make(4);\n"
      "#declare K = Local();\n"
      "#declare Arr = array[2] { M, K }\n"
      "#debug concat(vstr(3, M(0.25), \",\", 0, 6), \" \", vstr(2, K(1), \",\", 0, 6), \" \",\n"
      "              vstr(3, Arr[0](0.5), \",\", 0, 6), \"\\n\")\n");
  EXPECT_EQ(out,
            "1.000000,0.000000,0.000000 2.000000,0.000000,-0.000000\n"
            "1.125000,0.500000,-0.062500 2.174107,0.486607,-0.080357\n"
            "1.000000,1.000000,0.000000 2.000000,1.000000,0.000000\n"
            "3.000000,1.000000,0.000000 3.000000,3.000000 2.000000,2.000000,0.000000\n");
}

TEST(Spline, ALocalSplineReturnedByAMacroMayBeCalledAtOnce) {
  // `S()(1)` in a #declare: the call's '(' ends the macro whose local the spline is. POV-Ray 3.7.0.10 printed
  // this line for the same scene.
  EXPECT_EQ(debug_output("#version 3.7;\n"
                         "#macro S() #local Q = spline { 0, <1,0,0> 2, <5,0,0> } Q #end\n"
                         "#declare V = S()(1) + 1;\n"
                         "#debug concat(vstr(3, V, \",\", 0, 3), \" \", vstr(3, S()(0.5) * 2, \",\", 0, 3), \"\\n\")\n"),
            "4.000,1.000,1.000 4.000,0.000,0.000\n");
}

TEST(Spline, FunctionOfASplineIsAVectorFunctionOfT) {
  const std::string g = "#declare U = spline { 3, <3,3,3>, 1, <1,1,1>, 2, <2,2,2> }\n"
                        "#declare G = function { spline { U } }\n";
  expect_vector("G(1.5)", g, {1.5, 1.5, 1.5});
  EXPECT_NEAR(eval_float("H(1.5, 0, 0)", g + "#declare H = function { G(x).y + 1 }\n"), 2.5, 1e-12);
}

TEST(Spline, MalformedSplinesAndCallsAreLocatedErrors) {
  expect_error("#declare S = spline { }\n", 2, 23, "a spline entry 'T, V'");
  expect_error("#declare S = spline { linear_spline }\n", 2, 37, "a spline entry 'T, V'");
  expect_error("#declare S = spline { 0, <1,2,3> cubic_spline 1, <2,3,4> }\n", 2, 34,
               "must come before the spline's entries");
  expect_error("#declare S = spline { 0, \"a\" }\n", 2, 26, "a float or vector value");
  expect_error("#declare S = spline { 0, rgb <1,2,3> }\n", 2, 26, "no colour keyword");
  const std::string s = "#declare S = spline { 0, <1,2,3> 1, <2,3,4> }\n";
  expect_error(s + "#declare V = S(0.5, bezier_spline);\n", 3, 21, "linear_spline, quadratic_spline");
  expect_error(s + "#declare V = S(0.5, 1);\n", 3, 21, "linear_spline, quadratic_spline");
  expect_error(s + "#declare V = S(0.5 0.3);\n", 3, 20, "')' closing the call of the spline 'S'");
  expect_error(s + "#declare V = S(0.5, linear_spline, 3);\n", 3, 34, "')' closing the call");
  expect_error(s + "#declare V = S + 1;\n", 3, 16, "an incomplete spline call");
  expect_error(s + "#declare V = vlength(S);\n", 3, 23, "'(' after the spline 'S'");
  expect_error("#declare G = function(a) { spline { 0, 1 } }\n", 2, 28, "not allowed");
}

}  // namespace
}  // namespace povtrace::test

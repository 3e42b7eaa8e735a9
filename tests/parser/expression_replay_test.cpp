// Expressions read again in loops and macro bodies run as programs made from their kept tokens (expressions.cpp,
// "expression programs"): the values, warnings and errors must be those of the full parse, which the first round
// of a loop still takes and the same text outside a loop always takes.
#include <string>

#include <gtest/gtest.h>

#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

const std::string kPrelude =
    "#version 3.7;\n"
    "#declare A = 2; #declare B = -3; #declare Z = 0; #declare V = <1, 2, 3>; #declare W = <1, 2>;\n"
    "#declare C = rgb <0.1, 0.2, 0.3>; #declare F5 = <1, 2, 3, 4, 5>;\n";

// `expr` printed once at the top level, and in each of three rounds of a #while loop: both through vstr() (the
// parameter level) and as a declared value.
std::string once(const std::string& expr) {
  return "#declare Q = " + expr + ";\n#debug concat(vstr(5, " + expr + ", \" \", 0, 9), \" \", vstr(5, Q, \" \", 0, 9), \"\\n\")\n";
}

class ReplayedExpression : public ::testing::TestWithParam<const char*> {};

TEST_P(ReplayedExpression, GivesWhatTheParseGives) {
  const std::string expr = GetParam();
  const std::string straight = debug_output(kPrelude + once(expr));
  ASSERT_FALSE(straight.empty());
  const std::string looped =
      debug_output(kPrelude + "#declare R = 0;\n#while (R < 3)\n" + once(expr) + "#declare R = R + 1;\n#end\n");
  EXPECT_EQ(looped, straight + straight + straight) << expr;
}

// The same loop with expression programs off (ParseOptions::expression_programs): the full parse reads every round,
// and gives what the programs gave.
TEST_P(ReplayedExpression, GivesWhatTheProgramsGive) {
  const std::string expr = GetParam();
  const std::string scene =
      kPrelude + "#declare R = 0;\n#while (R < 3)\n" + once(expr) + "#declare R = R + 1;\n#end\n";
  Messages with, without;
  parse_scene_text(scene, "test.pov", options_into(with));
  ParseOptions off = options_into(without);
  off.expression_programs = false;
  parse_scene_text(scene, "test.pov", off);
  ASSERT_FALSE(with.items.empty());
  EXPECT_EQ(without.items, with.items) << expr;
}

INSTANTIATE_TEST_SUITE_P(
    Values, ReplayedExpression,
    ::testing::Values("A + B * 2", "-A - -B", "!A + !Z", "A / 4", "(A < B) + (A >= B) * 2", "(A = 2.00000000001)",
                      "(A != B & 1 | 0)", "(A & Z | !Z)", "(1 < 2 < 3)", "<A, B, 3>", "<A B>", "<A, B,>",
                      "<A, B, 3, 4, 5>", "V * 2 + A", "V / <1, 2, 4>", "-V", "!V", "W + V", "C * 0.5 + 1",
                      "C - V", "F5 * A", "mod(7, A)", "div(-7, A)", "int(-0.3)", "abs(B)", "min(A, B, 5)",
                      "mod(A B) + max(A, B)", "select(B, 1, 2)", "select(Z, 1, 2, 3)", "pow(A, 3)", "sqrt(A + 2)",
                      "sin(A) + cos(B)", "floor(A / 3) + ceil(B / 2)", "pi * A", "true + on - off", "-(A)",
                      "+A", "((A))", "2 * -A", "A * (B < 0)", "atan2(A, B)", "V.y + A", "(A ? 1 : 2)",
                      "vlength(V) + A", "<mod(A, 3) * 0.06 - 9.6, div(A, 3) * 0.06, 0>", "A+(B*0.5-3)/7"));

// An identifier that changes type between rounds: the program made in the second round meets a vector and a
// string, and the parse reads those rounds as it always does.
TEST(ReplayedExpressions, FollowTheTypesOfTheirIdentifiers) {
  const std::string out = debug_output(
      "#version 3.7;\n#declare X = 1;\n#declare R = 0;\n#while (R < 4)\n"
      "  #declare Y = X * 2 + 1;\n"
      "  #debug concat(vstr(3, Y, \",\", 0, 1), \"\\n\")\n"
      "  #if (R = 1) #declare X = <1, 2, 3>; #end\n"
      "  #if (R = 2) #declare X = rgb 1; #end\n"
      "  #declare R = R + 1;\n#end\n");
  EXPECT_EQ(out, "3.0,0.0,0.0\n3.0,0.0,0.0\n3.0,5.0,7.0\n3.0,3.0,3.0\n");
}

// The division by zero warns in every round, where the parse warns.
TEST(ReplayedExpressions, WarnInEveryRound) {
  Messages m;
  parse("#version 3.7;\n#declare D = 0;\n#declare R = 0;\n#while (R < 3)\n  #declare Q = 1 / D;\n"
        "  #declare R = R + 1;\n#end\n",
        &m);
  ASSERT_EQ(m.items.size(), 3u);
  EXPECT_NE(m.items[0].find("division by zero"), std::string::npos) << m.items[0];
  EXPECT_EQ(m.items[1], m.items[0]);
  EXPECT_EQ(m.items[2], m.items[0]);
}

// An error met in a later round is the error of the same text reached straight away.
TEST(ReplayedExpressions, FailWhereTheParseFails) {
  const std::string body = "  #declare Y = (X < 2) + mod(3, X);\n";
  const ParseError late = parse_error("#version 3.7;\n#declare X = 1;\n#declare R = 0;\n#while (R < 3)\n" + body +
                                      "  #if (R = 1) #declare X = <1, 2, 3>; #end\n  #declare R = R + 1;\n#end\n");
  const ParseError first = parse_error("#version 3.7;\n#declare X = <1,2,3>;\n#declare R = 0;\n#while (R < 3)\n" +
                                       body + "  #declare R = R + 1;\n#end\n");
  EXPECT_EQ(late.location().line, first.location().line);
  EXPECT_EQ(late.location().column, first.location().column);
  EXPECT_EQ(late.bare_message(), first.bare_message());
  const ParseError zero = parse_error("#version 3.7;\n#declare X = 1;\n#declare R = 0;\n#while (R < 3)\n" + body +
                                      "  #declare X = X - 1;\n  #declare R = R + 1;\n#end\n");
  EXPECT_EQ(zero.location().line, 5);
  EXPECT_NE(zero.bare_message().find("mod by zero"), std::string::npos) << zero.bare_message();
}

// Macro bodies replay their tokens on every call; arguments bound by alias write through.
TEST(ReplayedExpressions, InMacroBodies) {
  const std::string out = debug_output(
      "#version 3.7;\n#macro Add(P, Q) (P + Q * 0.5) #end\n#macro Inc(P) #declare P = P + 1; #end\n"
      "#declare S = 0; #declare I = 0;\n"
      "#while (I < 5) #declare S = Add(S, I); Inc(I) #end\n"
      "#declare T = Add(Add(1, 2), Add(S, 3));\n"
      "#debug concat(str(S, 0, 3), \" \", str(T, 0, 3), \" \", str(I, 0, 0), \"\\n\")\n");
  EXPECT_EQ(out, "5.000 5.250 5\n");
}

}  // namespace
}  // namespace povtrace::test

namespace povtrace::test {
namespace {

// Between statements of the main file the tokens already read are freed in chunks of 4096
// (FileTokens::release_before), except from where a macro body starts: a macro defined before 50,000 tokens of
// #declares still runs, loops still replay, and errors far down still say where they are.
TEST(KeptTokens, FreedBehindTheStatementsButNotUnderMacros) {
  std::string scene = "#version 3.7;\n#macro Twice(A) (A * 2) #end\n";
  for (int i = 0; i < 10000; ++i) scene += "#declare V" + std::to_string(i) + " = " + std::to_string(i) + ";\n";
  scene += "#declare R = 0; #while (R < 3) #declare R = R + 1; #end\n";
  for (int i = 0; i < 10000; ++i) scene += "#local W" + std::to_string(i) + " = V" + std::to_string(i) + " + 1;\n";
  scene += "#debug concat(str(Twice(V9999 + W5), 0, 1), \" \", str(R, 0, 0), \"\\n\")\n";
  EXPECT_EQ(debug_output(scene), "20010.0 3\n");
  const ParseError e = parse_error(scene + "#declare X = 1 + ;\n");
  EXPECT_EQ(e.location().line, 20005);
  EXPECT_EQ(e.location().column, 18);
}

}  // namespace
}  // namespace povtrace::test

// Inputs found by fuzzing the front end (fuzz/, scripts/fuzz.sh) or while auditing what the fuzzer reported,
// kept as regression tests: each must end in a ParseError or a clean parse — never a crash, a sanitizer report
// (scripts/test_sanitized.sh runs these under ASan/UBSan) or another exception. Values are checked where the
// outcome is defined.
#include <string>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

// Out-of-range floats where an integer is needed: converting them was undefined behaviour (UBSan
// float-cast-overflow); they now saturate, NaN counts as 0.
TEST(FuzzRegressions, StrWithHugeWidthAndPrecision) {
  EXPECT_EQ(debug_output("#version 3.7;\n#debug str(1, 1e300, -1e300)\n").size(), 511u);
  EXPECT_EQ(debug_output("#version 3.7;\n#debug str(1.5, -1e300, 1)\n").size(), 511u);
  Messages m;
  parse("#version 3.7;\n#debug str(2.25, 0, 0/0)\n", &m);   // a division-by-zero warning, then the text
  ASSERT_EQ(m.items.size(), 2u);
  EXPECT_EQ(m.items[1], "2");
  // A precision of 2·10^9 made snprintf allocate 8 GB.
  EXPECT_EQ(debug_output("#version 3.7;\n#debug str(1, 0, 2e9)\n"), "1." + std::string(509, '0'));
}

TEST(FuzzRegressions, VstrAndChrWithHugeArguments) {
  EXPECT_NO_THROW(parse("#version 3.7;\n#declare S = vstr(1e300, <1,2,3>, \",\", 1e300, -1e300);\n"));
  EXPECT_NO_THROW(parse("#version 3.7;\n#declare S = vstr(-1e300, <1,2,3>, \",\", 0/0, 0/0);\n"));
  EXPECT_EQ(debug_output("#version 3.7;\n#debug chr(65 + 1e300 * 0)\n#declare C = chr(1e300);\n"), "A");
}

TEST(FuzzRegressions, SubstrOutOfRangeIsAnError) {
  for (const char* args : {"2147483647, 2147483647", "1e300, 1", "1, 1e300", "-1e300, 1", "0/0, 1"}) {
    const ParseError e = parse_error(std::string("#version 3.7;\n#declare S = substr(\"abc\", ") + args + ");\n");
    EXPECT_NE(e.bare_message().find("is out of range"), std::string::npos) << args << ": " << e.bare_message();
  }
  EXPECT_EQ(debug_output("#version 3.7;\n#debug substr(\"abc\", 2, 2)\n"), "bc");
}

TEST(FuzzRegressions, BitwiseFunctionsSaturate) {
  EXPECT_EQ(eval_float("bitwise_and(1e300, 7)"), 7);
  EXPECT_EQ(eval_float("bitwise_or(-1e300, 0)"), -9223372036854775808.0);
  EXPECT_EQ(eval_float("bitwise_xor(0/0, 5)"), 5);
}

TEST(FuzzRegressions, SeedAndRandWithHugeOrNaNStreams) {
  EXPECT_NO_THROW(parse("#version 3.7;\n#declare R = seed(1e300);\n#declare X = rand(R);\n#declare Q = seed(0/0);\n"));
  for (const char* stream : {"-1", "1e300", "-1e300", "0/0"}) {
    const ParseError e = parse_error(std::string("#version 3.7;\n#declare R = seed(1);\n#declare X = rand(") +
                                     stream + ");\n");
    EXPECT_NE(e.bare_message().find("seed() did not create"), std::string::npos) << stream;
  }
}

TEST(FuzzRegressions, MaxTraceLevelOutOfRange) {
  EXPECT_EQ(parse("#version 3.7;\nglobal_settings { max_trace_level 1e300 }\n").settings.max_trace_level, 256);
  EXPECT_EQ(parse("#version 3.7;\nglobal_settings { max_trace_level -1e300 }\n").settings.max_trace_level, 1);
}

TEST(FuzzRegressions, CaseOfBytesAbove127) {
  EXPECT_EQ(debug_output("#version 3.7;\n#debug strupr(\"a\xe9z\")\n"), "A\xe9Z");
  EXPECT_EQ(debug_output("#version 3.7;\n#debug strlwr(\"A\xc9Z\")\n"), "a\xc9z");
}

// The token limit the fuzzer runs with (ParseOptions::max_tokens) ends a runaway #while with an error.
TEST(FuzzRegressions, TokenLimitEndsARunawayLoop) {
  ParseOptions o;
  o.max_tokens = 10000;
  const ParseError e = parse_error("#version 3.7;\n#while (1)\n  #declare A = 1;\n#end\n", o);
  EXPECT_EQ(e.bare_message(), "the parse read more than 10000 tokens (the token limit of this run)");
  EXPECT_NO_THROW(parse_scene_text("#version 3.7;\nsphere { 0, 1 }\n", "test.pov", o));
}

}  // namespace
}  // namespace povtrace::test

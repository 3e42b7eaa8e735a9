// Malformed scenes: every error names file:line:column, quotes the line with a caret under the column and says
// what was expected (STYLE.md "Test error text and its position exactly"). Also: warnings that must not be
// errors, unsupported features named as such, and hostile input (self-inclusion, runaway recursion, binary
// garbage, very long lines) that must fail cleanly rather than crash.
#include <atomic>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

struct ErrorCase {
  std::string name;
  std::string text;
  int line, column;
  std::string fragment;   // part of the bare message
};

class Errors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(Errors, LocationCaretAndMessage) {
  const ErrorCase& c = GetParam();
  const ParseError e = parse_error(c.text);
  EXPECT_EQ(e.location().file_name(), "test.pov");
  EXPECT_EQ(e.location().line, c.line) << e.what();
  EXPECT_EQ(e.location().column, c.column) << e.what();
  EXPECT_NE(e.bare_message().find(c.fragment), std::string::npos) << e.bare_message();
  // what() = "file:line:col: error: message\n<the source line>\n<caret under the column>".
  std::string line_text;
  {
    std::size_t begin = 0;
    for (int l = 1; l < c.line && begin != std::string::npos; ++l) {
      begin = c.text.find('\n', begin);
      if (begin != std::string::npos) ++begin;
    }
    if (begin != std::string::npos && begin <= c.text.size())
      line_text = c.text.substr(begin, c.text.find('\n', begin) - begin);
  }
  const std::string expected = "test.pov:" + std::to_string(c.line) + ":" + std::to_string(c.column) +
                               ": error: " + e.bare_message() + "\n" + line_text + "\n" +
                               std::string(static_cast<std::size_t>(std::max(0, c.column - 1)), ' ') + "^" +
                               (e.context().empty() ? "" : "\n" + e.context());
  EXPECT_EQ(std::string(e.what()), expected);
}

INSTANTIATE_TEST_SUITE_P(
    Syntax, Errors,
    ::testing::Values(
        ErrorCase{"MissingBraceAtEndOfFile", "#version 3.7;\nsphere { 0, 1\n", 3, 1, "or '}', found the end of the file"},
        ErrorCase{"MissingBraceBeforeNextObject", "#version 3.7;\nsphere { 0, 1\nsphere { 0, 2 }\n", 3, 1,
                  "or '}', found the keyword 'sphere'"},
        ErrorCase{"MissingRadius", "#version 3.7;\nsphere { <0,0,0> }\n", 2, 18,
                  "expected a number, vector or expression, found '}'"},
        ErrorCase{"MissingBraceAfterCamera", "#version 3.7;\ncamera { location <0,0,-5>\n", 3, 1,
                  "found the end of the file"},
        ErrorCase{"DeclareWithoutSemicolon", "#version 3.7;\n#declare X = 1\nsphere { 0, 1 }\n", 3, 1,
                  "expected ';' after the value of X, found the keyword 'sphere'"},
        ErrorCase{"UndeclaredIdentifier", "#version 3.7;\nsphere { 0, R }\n", 2, 13, "undeclared identifier 'R'"},
        ErrorCase{"UndeclaredAtTopLevel", "#version 3.7;\nSphere { 0, 1 }\n", 2, 1,
                  "found the undeclared identifier 'Sphere'"},
        ErrorCase{"ReservedWordDeclared", "#version 3.7;\n#declare sphere = 1;\n", 2, 10,
                  "'sphere' is a reserved word and cannot be declared"},
        ErrorCase{"ReservedWordAsMacroName", "#version 3.7;\n#macro box() #end\n", 2, 8, "'box' is a reserved word"},
        ErrorCase{"IfWithoutParentheses", "#version 3.7;\n#declare K = 1;\n#if K #debug \"x\" #end\n", 3, 5,
                  "expected '(' (conditions are written in parentheses), found the float identifier 'K'"},
        ErrorCase{"UnterminatedIfTaken", "#version 3.7;\n#if (1)\nsphere { 0, 1 }\n", 2, 2, "expected '#end'"},
        ErrorCase{"UnterminatedIfSkipped", "#version 3.7;\n#if (0)\nsphere { 0, 1 }\n", 2, 2, "has no matching #end"},
        ErrorCase{"UnterminatedWhile", "#version 3.7;\n#declare I = 0;\n#while (I < 2) #declare I = I + 1;\n", 3, 2,
                  "expected '#end'"},
        ErrorCase{"UnterminatedMacroDefinition", "#version 3.7;\n#macro M()\n  sphere { 0, 1 }\n", 2, 2,
                  "has no matching #end"},
        ErrorCase{"EndAlone", "#version 3.7;\n#end\n", 2, 2, "#end without a matching #if"},
        ErrorCase{"ElseAlone", "#version 3.7;\n  #else\n", 2, 4, "#else without a matching #if"},
        ErrorCase{"UnknownDirective", "#version 3.7;\n#foo\n", 2, 2, "found the undeclared identifier 'foo'"},
        ErrorCase{"StraySemicolon", "#version 3.7;\nsphere { 0, 1 };\n", 2, 16, "unexpected ';'"},
        ErrorCase{"PolyOrderAboveMaxOrder", "#version 3.7;\npoly { 36, <1> }\n", 2, 8, "the order of a poly must be 2 to 35"},
        ErrorCase{"PolyTooManyCoefficients", "#version 3.7;\npoly { 2, <1,2,3,4,5,6,7,8,9,10,11> }\n", 2, 32,
                  "expected '>' after the 10 coefficients of a poly of order 2, found ','"},
        ErrorCase{"DeclareWithoutHash", "#version 3.7;\ndeclare X = 1;\n", 2, 1, "'#declare'"},
        ErrorCase{"MacroCallWithTooManyArguments", "#version 3.7;\n#macro M(A) A #end\n#declare B = M(1, 2);\n", 3,
                  17, "')' closing the call of macro 'M' (it takes 1 parameters)"},
        ErrorCase{"WrongValueType", "#version 3.7;\n#declare S = \"s\";\nsphere { 0, S }\n", 3, 13,
                  "found the string identifier 'S'"},
        ErrorCase{"VectorWhereAFloatIsNeeded", "#version 3.7;\nsphere { 0, <1,2,3> }\n", 2, 13,
                  "expected a float, found a vector"},
        ErrorCase{"PigmentNeedsAColourKeyword", "#version 3.7;\nsphere { 0, 1 pigment { <1,0,0> } }\n", 2, 25,
                  "expected a colour, a pattern, a transform or '}' in pigment { }"},
        ErrorCase{"ZeroPlaneNormal", "#version 3.7;\nplane { 0, 1 }\n", 2, 9, "the plane's normal is the zero vector"},
        ErrorCase{"CameraAngle", "#version 3.7;\ncamera { angle 180 }\n", 2, 10, "less than 180 degrees"},
        ErrorCase{"ErrorDirective", "#version 3.7;\n#error \"stop here\"\nsphere { 0, 1 }\n", 2, 2,
                  "#error: stop here"},
        ErrorCase{"ErrorInsideAMacroPointsIntoTheBody",
                  "#version 3.7;\n#macro M()\n  sphere { 0, Q }\n#end\nM()\n", 3, 15, "undeclared identifier 'Q'"},
        ErrorCase{"UnterminatedString", "#version 3.7;\n#debug \"abc\n", 2, 8, "unterminated string"},
        ErrorCase{"UnterminatedComment", "#version 3.7;\n/* a /* b */\nsphere{0,1}\n", 2, 1,
                  "unterminated block comment"},
        // The lexer reads ahead of the parse (FileTokens::lex_quick_run), but what it cannot read quickly — an
        // illegal character, an unterminated string — is reported only when the parse reaches it: an earlier
        // error in the parse comes first, at its own place.
        ErrorCase{"ParseErrorBeforeALexicalErrorAhead", "#version 3.7;\nsphere { 0, Q }\n#declare A = 1 \x01 2;\n",
                  2, 13, "undeclared identifier 'Q'"},
        ErrorCase{"ErrorDirectiveBeforeAnUnterminatedStringAhead",
                  "#version 3.7;\n#declare A = 1;\n#error \"stop here\"\n#declare B = 2 + 3;\n#debug \"open\n", 3, 2,
                  "stop here"},
        ErrorCase{"LexicalErrorAfterTokensReadAhead", "#declare A = <1, 2, 3> * 2;\n#declare B = A + 1; /* open\n", 2,
                  21, "unterminated block comment"}),
    [](const auto& p) { return p.param.name; });

// Features povtrace does not render: they parse, and placing them in the scene is the error — at the position
// of the statement that places them, naming the feature and where it is written (issue 3).
INSTANTIATE_TEST_SUITE_P(
    Unsupported, Errors,
    ::testing::Values(
        ErrorCase{"Normal", "#version 3.7;\nsphere { 0, 1 normal { tiling 3 } }\n", 2, 1,
                  "unsupported: the normal item 'tiling'"},
        ErrorCase{"NormalInTexture", "#version 3.7;\nsphere { 0, 1 texture { normal { pavement 0.5 } } }\n", 2, 1,
                  "unsupported: the normal item 'pavement'"},
        ErrorCase{"Subsurface", "#version 3.7;\nsphere { 0, 1 finish { subsurface { translucency 0.3 } } }\n", 2, 1,
                  "unsupported: the finish item 'subsurface'"},
        ErrorCase{"SphereSweep", "#version 3.7;\nsphere_sweep { linear_spline 2, <0, 0, 0>, 1, <1, 0, 0>, 1 }\n", 2,
                  1, "unsupported: the shape 'sphere_sweep'"},
        ErrorCase{"Pavement", "#version 3.7;\nsphere { 0, 1 pigment { pavement } }\n", 2, 1,
                  "unsupported: the pigment item 'pavement'"},
        ErrorCase{"CutawayTextures", "#version 3.7;\nsphere { 0, 1 cutaway_textures }\n", 2, 1,
                  "unsupported: the object modifier 'cutaway_textures'"},
        ErrorCase{"Bokeh", "#version 3.7;\ncamera { bokeh { pigment { rgb 1 } } }\n", 2, 1,
                  "unsupported: the camera item 'bokeh'"}),
    [](const auto& p) { return p.param.name; });

// Cameras POV-Ray 3.7 refuses (Parse_Camera), and those it renders with NaN or directionless rays (a picture of the
// background colour) which povtrace refuses instead: each at the item that causes it.
INSTANTIATE_TEST_SUITE_P(
    Camera, Errors,
    ::testing::Values(
        ErrorCase{"LocationEqualsLookAt", "#version 3.7;\ncamera { location <0,1,0> look_at <0,1,0> }\n", 2, 27,
                  "Camera location and look_at point must be different."},
        ErrorCase{"DefaultLocationEqualsLookAt", "#version 3.7;\ncamera { look_at 0 }\n", 2, 10,
                  "Camera location and look_at point must be different."},
        ErrorCase{"LookAtBeforeLocation", "#version 3.7;\ncamera { look_at <0,1,0> location <0,1,0> }\n", 2, 10,
                  "Camera location and look_at point must be different."},
        ErrorCase{"LookAtEqualBeforeTheTransforms",
                  "#version 3.7;\ncamera { location 1 look_at 1 translate x }\n", 2, 21,
                  "Camera location and look_at point must be different."},
        ErrorCase{"FisheyeLocationEqualsLookAt", "#version 3.7;\ncamera { fisheye location 2 look_at 2 }\n", 2, 29,
                  "Camera location and look_at point must be different."},
        ErrorCase{"NegativeAngle", "#version 3.7;\ncamera { angle -1 }\n", 2, 10, "must not be negative"},
        ErrorCase{"OrthographicAngle180", "#version 3.7;\ncamera { orthographic angle 180 }\n", 2, 23,
                  "less than 180 degrees"},
        ErrorCase{"TypeAfterAnItem", "#version 3.7;\ncamera { location -5*z orthographic }\n", 2, 24,
                  "the camera type 'orthographic' must come first in camera { }"},
        ErrorCase{"ZeroDirectionWithAngle", "#version 3.7;\ncamera { direction 0 angle 60 }\n", 2, 10,
                  "the camera direction is the zero vector"},
        ErrorCase{"OrthographicZeroDirection",
                  "#version 3.7;\ncamera { orthographic location -5*z direction 0 }\n", 2, 37,
                  "the orthographic camera's direction is the zero vector"},
        ErrorCase{"AllVectorsZero", "#version 3.7;\ncamera { direction 0 up 0 right 0 }\n", 2, 1,
                  "direction, up and right vectors are all zero"},
        ErrorCase{"ZeroRightWithSkyParallel", "#version 3.7;\ncamera { location 5*y right 0 look_at 0 }\n", 2, 23,
                  "the camera right vector is zero and look_at is parallel to sky"},
        ErrorCase{"InfiniteLocation", "#version 3.7;\ncamera { location <1e300,0,0>*1e300 }\n", 2, 1,
                  "the camera's vectors must be finite"}),
    [](const auto& p) { return p.param.name; });

// ---- Warnings are not errors -------------------------------------------------------------------------------
TEST(Warnings, DivisionByZeroWarnsAndParsingGoesOn) {
  Messages m;
  const SceneDescription s = parse("#version 3.7;\n#declare A = 1/0;\nsphere { 0, 1 }\n", &m);
  EXPECT_EQ(s.objects.size(), 1u);
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_EQ(m.items[0], "test.pov:2:15: warning: division by zero\n#declare A = 1/0;\n              ^");
}

TEST(Warnings, DomainErrorsAndInfiniteResultsAreNamedWhereTheyAreMade) {
  // POV-Ray: "Domain error in acos" (a warning; the argument is clamped). pow(0, -1) and exp(1000) are infinite
  // in POV-Ray too, silently; povtrace names them.
  struct Case { const char* expression; const char* warning; int column; };
  for (const Case& c : {Case{"acos(2)", "domain error in acos", 14}, Case{"asin(-3)", "domain error in asin", 14},
                        Case{"pow(0, -1)", "pow gives an infinite value", 14},
                        Case{"exp(1000)", "exp gives an infinite value", 14}}) {
    Messages m;
    const SceneDescription s = parse(std::string("#version 3.7;\n#declare A = ") + c.expression + ";\nsphere { 0, 1 }\n", &m);
    EXPECT_EQ(s.objects.size(), 1u) << c.expression;
    ASSERT_EQ(m.items.size(), 1u) << c.expression;
    EXPECT_EQ(m.items[0].rfind("test.pov:2:" + std::to_string(c.column) + ": warning: " + c.warning, 0), 0u)
        << m.items[0];
  }
}

TEST(Warnings, MissingCommaIsAcceptedLikePovRay) {
  // POV-Ray's Parse_Comma makes the comma between object parameters optional (povray parses this scene).
  const SceneDescription s = parse("#version 3.7;\nsphere { <0,0,0> 1 }\nbox { <0,0,0> <1,1,1> }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).radius, 1);
}

// ---- Include files ----------------------------------------------------------------------------------------
TEST(IncludeErrors, FileNotFound) {
  ScratchFolder lib;
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_nowhere.inc\"\n", o);
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 10);
  EXPECT_NE(e.bare_message().find("cannot find include file \"ptest_nowhere.inc\""), std::string::npos)
      << e.bare_message();
  EXPECT_NE(e.bare_message().find(lib.path().string()), std::string::npos) << "names the searched folders";
}

// Found by the parse fuzzer: a name longer than the file system allows made std::filesystem throw out of the
// include search (and so out of the parser). It is a file that cannot be found, reported at its position.
TEST(IncludeErrors, NameTooLongForTheFileSystemIsNotFound) {
  const std::string name(5000, 'n');
  const ParseError e = parse_error("#version 3.7;\n#include \"" + name + "\"\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 10);
  EXPECT_NE(e.bare_message().find("cannot find include file"), std::string::npos) << e.bare_message();
}

TEST(IncludeErrors, FileExistsOfANameTooLongIsFalse) {
  const std::string name(5000, 'n');
  EXPECT_EQ(debug_output("#version 3.7;\n#debug str(file_exists(\"" + name + "\"), 0, 0)\n"), "0");
}

TEST(IncludeErrors, SelfIncludingFileFailsCleanly) {
  ScratchFolder lib;
  const auto self = lib.write("ptest_self.inc", "#declare N = 1;\n#include \"ptest_self.inc\"\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_self.inc\"\n", o);
  EXPECT_NE(e.bare_message().find("too many nested"), std::string::npos) << e.bare_message();
  EXPECT_EQ(e.location().file_name(), self.string());
  EXPECT_EQ(e.location().line, 2);
}

TEST(IncludeErrors, ErrorInAnIncludeNamesThatFile) {
  ScratchFolder lib;
  const auto inc = lib.write("ptest_broken.inc", "#declare A = 1;\n  sphere { 0, Nope }\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_broken.inc\"\n", o);
  EXPECT_EQ(e.location().file_name(), inc.string());
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 15);
  EXPECT_EQ(std::string(e.what()), inc.string() + ":2:15: error: " + e.bare_message() +
                                       "\n  sphere { 0, Nope }\n              ^\n  included from test.pov:2:1");
}

TEST(IncludeErrors, IfOpenedInAnIncludeMustCloseThere) {
  ScratchFolder lib;
  lib.write("ptest_open_if.inc", "#if (1)\n#declare A = 1;\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_open_if.inc\"\n#end\n", o);
  EXPECT_NE(e.bare_message().find("expected '#end'"), std::string::npos) << e.bare_message();
  EXPECT_EQ(e.location().line, 1);
}

TEST(IncludeErrors, MissingSceneFile) {
  ScratchFolder dir;
  try {
    parse_scene(dir.path() / "absent.pov", ParseOptions{});
    ADD_FAILURE() << "expected an error";
  } catch (const ParseError& e) {
    EXPECT_NE(e.bare_message().find("absent.pov"), std::string::npos) << e.what();
  }
}

// ---- Error chains: how an error inside an include file or a macro body was reached ------------------------------
// After the caret block, one line per level, innermost first (issue 3 item 8).
TEST(ErrorChains, ErrorInAMacroNamesTheCall) {
  const ParseError e = parse_error("#version 3.7;\n#macro Foo()\n  sphere { 0, Q }\n#end\n  Foo()\n");
  EXPECT_EQ(std::string(e.what()), "test.pov:3:15: error: " + e.bare_message() +
                                       "\n  sphere { 0, Q }\n              ^\n  in macro Foo called from test.pov:5:3");
  EXPECT_EQ(e.context(), "  in macro Foo called from test.pov:5:3");
}

TEST(ErrorChains, MacroCalledFromAMacroInAnInclude) {
  ScratchFolder lib;
  const auto inc = lib.write("ptest_chain.inc",
                             "#macro Inner(A)\n"
                             "  sphere { 0, A + Nope }\n"
                             "#end\n"
                             "#macro Outer(B)\n"
                             "  union { Inner(B) sphere { 0, 1 } }\n"
                             "#end\n"
                             "Outer(2)\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_chain.inc\"\n", o);
  EXPECT_EQ(std::string(e.what()), inc.string() + ":2:19: error: undeclared identifier 'Nope'\n"
                                                  "  sphere { 0, A + Nope }\n"
                                                  "                  ^\n"
                                                  "  in macro Inner called from " + inc.string() + ":5:11\n"
                                                  "  in macro Outer called from " + inc.string() + ":7:1\n"
                                                  "  included from test.pov:2:1");
}

TEST(ErrorChains, MacrosFromAnIncludeCalledInTheScene) {
  // The include file is finished when the macro runs: the chain is the calls, not the #include.
  ScratchFolder lib;
  const auto inc = lib.write("ptest_chain2.inc", "#macro Inner(A) #error concat(\"bad \", str(A, 0, 0)) #end\n"
                                                 "#macro Outer(B) Inner(B + 1) #end\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_chain2.inc\"\n#declare X = 1;\nOuter(X)\n", o);
  EXPECT_EQ(e.bare_message(), "#error: bad 2");
  EXPECT_EQ(e.context(), "  in macro Inner called from " + inc.string() + ":2:17\n"
                         "  in macro Outer called from test.pov:4:1");
}

TEST(ErrorChains, NestedIncludes) {
  ScratchFolder lib;
  const auto outer = lib.write("ptest_outer.inc", "#declare A = 1;\n  #include \"ptest_inner.inc\"\n");
  const auto inner = lib.write("ptest_inner.inc", "#error \"stop\"\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n\n#include \"ptest_outer.inc\"\n", o);
  EXPECT_EQ(std::string(e.what()), inner.string() + ":1:2: error: #error: stop\n#error \"stop\"\n ^\n"
                                   "  included from " + outer.string() + ":2:3\n"
                                   "  included from test.pov:3:1");
}

TEST(ErrorChains, LexerErrorsInAnIncludeHaveTheChainToo) {
  ScratchFolder lib;
  const auto inc = lib.write("ptest_lex.inc", "#declare A = 1;\n#declare S = \"open\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_lex.inc\"\n", o);
  EXPECT_EQ(e.location().file_name(), inc.string());
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.context(), "  included from test.pov:2:1");
  EXPECT_TRUE(std::string(e.what()).ends_with("^\n  included from test.pov:2:1")) << e.what();
}

TEST(ErrorChains, WarningsInAMacroNameTheCall) {
  Messages m;
  parse("#version 3.7;\n#macro Half(A) (A / 0) #end\n#declare H = Half(1);\n", &m);
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_EQ(m.items[0], "test.pov:2:19: warning: division by zero\n#macro Half(A) (A / 0) #end\n                  ^\n"
                        "  in macro Half called from test.pov:3:14");
}

TEST(ErrorChains, RunawayRecursionShowsTheInnermostAndOutermostCalls) {
  const ParseError e = parse_error("#version 3.7;\n#macro R(N) R(N+1) #end\nR(0)\n");
  const std::string& c = e.context();
  std::vector<std::string> lines;
  for (std::size_t b = 0; b <= c.size();) {
    std::size_t end = c.find('\n', b);
    if (end == std::string::npos) end = c.size();
    lines.push_back(c.substr(b, end - b));
    b = end + 1;
  }
  ASSERT_EQ(lines.size(), 16u) << c;
  EXPECT_EQ(lines[0], "  in macro R called from test.pov:2:13");
  EXPECT_EQ(lines[10], "  ... 241 more levels ...");
  EXPECT_EQ(lines[15], "  in macro R called from test.pov:3:1");
}

// ---- Runaway recursion, garbage, long lines -------------------------------------------------------------------
TEST(Robustness, RunawayMacroRecursionFailsCleanly) {
  const ParseError e = parse_error("#version 3.7;\n#macro R(N) R(N+1) #end\nR(0)\n");
  EXPECT_NE(e.bare_message().find("nested too deeply"), std::string::npos) << e.bare_message();
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 13);
}

TEST(Robustness, RunawayRecursionInsideAnExpressionFailsCleanly) {
  const ParseError e = parse_error("#version 3.7;\n#macro F(N) (1 + F(N+1)) #end\n#declare A = F(0);\n");
  EXPECT_NE(e.bare_message().find("nested too deeply"), std::string::npos) << e.bare_message();
}

TEST(Robustness, NulBytesAreBlanks) {
  const std::string text = std::string("#version 3.7;\n\0sphere {\0 0, 1 }\0\n", 32);
  const SceneDescription s = parse(text);
  EXPECT_EQ(s.objects.size(), 1u);
}

TEST(Robustness, BinaryGarbageIsALocatedError) {
  const std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x08", 20);
  const ParseError e = parse_error(png);
  EXPECT_EQ(e.location().line, 1);
  EXPECT_EQ(e.location().column, 1);
  EXPECT_NE(e.bare_message().find("illegal character 0x89"), std::string::npos) << e.bare_message();
  // The echoed line never carries raw control bytes.
  const std::string what = e.what();
  for (char c : what.substr(what.find('\n')))
    EXPECT_FALSE(static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') << static_cast<int>(c);
}

// Random bytes and random token soup: a ParseError or a clean parse, never another exception or a crash.
TEST(Robustness, RandomInputNeverEscapesAsAnotherException) {
  const std::vector<std::string> vocabulary = {
      "sphere", "box", "plane", "{", "}", "<", ">", ",", "(", ")", "#declare", "#local", "#if", "#else", "#end",
      "#ifdef", "#undef", "#include", "#version", "X", "Y", "=", ";", "1", "0", "-2.5", "x", "rgb", "color",
      "pigment", "finish", "texture", "checker", "translate", "rotate", "scale", "camera", "light_source", "object",
      "\"s\"", "+", "*", "/", ".", "?", ":", "|", "&", "!", "#macro", "M", "M(", "background", "global_settings",
      "location", "look_at", "angle", "ambient", "phong", "metallic", "vrotate", "str", "concat", "seed", "rand",
      "#debug", "#default", "transform", "inverse", "matrix", "[", "]"};
  std::mt19937 rng(12345);
  int errors = 0, parsed = 0;
  for (int round = 0; round < 400; ++round) {
    std::string text;
    if (round % 4 == 0) {
      const int n = static_cast<int>(rng() % 200);
      for (int i = 0; i < n; ++i) text += static_cast<char>(rng() % 256);
    } else {
      const int n = static_cast<int>(rng() % 40);
      for (int i = 0; i < n; ++i) text += vocabulary[rng() % vocabulary.size()] + (rng() % 3 ? " " : "\n");
    }
    try {
      Messages m;
      parse(text, &m);
      ++parsed;
    } catch (const ParseError& e) {
      ++errors;
      EXPECT_GE(e.location().line, 1) << text;
      EXPECT_GE(e.location().column, 1) << text;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "non-ParseError exception " << e.what() << " for input:\n" << text;
    }
  }
  EXPECT_GT(errors, 0);
  EXPECT_GT(parsed, 0);
}

TEST(Robustness, VeryLongLine) {
  // 100 000 characters on one line: "#declare A = 0+1+1+…+1;".
  std::string line = "#declare A = 0";
  while (line.size() < 100000) line += "+1";
  const std::size_t ones = (line.size() - 14) / 2;
  line += ";";
  EXPECT_EQ(debug_output("#version 3.7;\n" + line + "\n#debug str(A,0,0)\n"), std::to_string(ones));

  // An error at the far end of the long line is located by its byte column.
  std::string bad = line.substr(0, line.size() - 1) + " @;";
  const ParseError e = parse_error("#version 3.7;\n" + bad + "\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, static_cast<int>(bad.size()) - 1);
}

std::string repeat(const std::string& s, int n) {
  std::string out;
  for (int i = 0; i < n; ++i) out += s;
  return out;
}

struct NestingCase {
  std::string name;
  std::string open, middle, close;   // open × n, middle, close × n on line 2
  std::string prefix, suffix;
};

class DeepNesting : public ::testing::TestWithParam<NestingCase> {};

// 50 000 levels (POV-Ray itself crashes on these) must give a located error, not a stack overflow.
TEST_P(DeepNesting, FailsCleanly) {
  const NestingCase& c = GetParam();
  const std::string text = "#version 3.7;\n#declare S = sphere { 0, 1 }\n" + c.prefix +
                           repeat(c.open, 50000) + c.middle + repeat(c.close, 50000) + c.suffix + "\n";
  const ParseError e = parse_error(text);
  EXPECT_EQ(e.location().line, 3);
  EXPECT_GT(e.location().column, 500);
  EXPECT_NE(e.bare_message().find("nested too deeply"), std::string::npos) << e.bare_message();
}

// Up to a few hundred levels is fine.
TEST_P(DeepNesting, ModerateNestingParses) {
  const NestingCase& c = GetParam();
  const std::string text = "#version 3.7;\n#declare S = sphere { 0, 1 }\n" + c.prefix + repeat(c.open, 300) +
                           c.middle + repeat(c.close, 300) + c.suffix + "\n";
  EXPECT_NO_THROW(parse(text));
}

INSTANTIATE_TEST_SUITE_P(
    Table, DeepNesting,
    ::testing::Values(NestingCase{"Parentheses", "(", "1", ")", "#declare A = ", ";"},
                      NestingCase{"UnaryMinus", "-", "1", "", "#declare A = ", ";"},
                      NestingCase{"FunctionCalls", "abs(", "1", ")", "#declare A = ", ";"},
                      NestingCase{"VectorComponents", "<", "1,2", ">.x,0", "#declare A = <", ">;"},
                      NestingCase{"ObjectBlocks", "object { ", "S", " }", "", ""},
                      NestingCase{"TransformBlocks", "transform { ", "", " }", "sphere { 0, 1 ", " }"},
                      NestingCase{"Unions", "union { ", "object { S }", " }", "", ""},
                      NestingCase{"StringFunctions", "concat(\"x\", ", "strupr(\"a\")", ")", "#declare A = ", ";"},
                      NestingCase{"MacroArguments", "M(", "1", ")", "#macro M(P) P #end #declare A = ", ";"},
                      NestingCase{"ConditionalChain", "1 ? 1 : ", "1", "", "#declare A = (", ");"}),
    [](const auto& p) { return p.param.name; });

// Issue 3 item 7: input far deeper than any scene — a result or an error, never a stack overflow.
TEST(Limits, TwoHundredThousandParentheses) {
  const ParseError e = parse_error("#version 3.7;\n#declare A = " + repeat("(", 200000) + "1" + repeat(")", 200000) +
                                   ";\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_NE(e.bare_message().find("nested too deeply"), std::string::npos) << e.bare_message();
}

TEST(Limits, HundredThousandNestedUnions) {
  const ParseError e = parse_error("#version 3.7;\n" + repeat("union { ", 100000) + "sphere { 0, 1 }" +
                                   repeat(" }", 100000) + "\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_NE(e.bare_message().find("nested too deeply"), std::string::npos) << e.bare_message();
}

// Directives read their operands through the token stream, which runs the directives it meets: they nest too.
TEST(Limits, DirectivesInsideDirectives) {
  std::string declares;
  for (int i = 0; i < 100000; ++i) declares += "#declare A" + std::to_string(i) + " = ";
  for (const std::string& text : {"#version 3.7;\n" + declares + "1;\n", "#version 3.7;\n" + repeat("#if (", 100000) + "1)\n",
                                  "#version 3.7;\n" + repeat("#debug ", 100000) + "\"x\"\n"}) {
    const ParseError e = parse_error(text);
    EXPECT_EQ(e.location().line, 2);
    EXPECT_NE(e.bare_message().find("nested too deeply"), std::string::npos) << e.bare_message();
  }
}

TEST(Limits, IncludeDepth) {
  // a0.inc includes a1.inc … : 32 nested files are fine, the 33rd is refused at its #include.
  ScratchFolder lib;
  for (int i = 0; i < 40; ++i)
    lib.write("ptest_n" + std::to_string(i) + ".inc",
              i == 39 ? "#declare Deepest = 1;\n" : "#include \"ptest_n" + std::to_string(i + 1) + ".inc\"\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const ParseError e = parse_error("#version 3.7;\n#include \"ptest_n0.inc\"\n", o);
  EXPECT_EQ(e.bare_message(), "too many nested #include files (at most 32; does a file include itself?)");
  EXPECT_EQ(e.location().file_name(), (lib.path() / "ptest_n31.inc").string());
  EXPECT_EQ(e.location().line, 1);
  EXPECT_EQ(e.location().column, 1);
  Messages m;
  ParseOptions ok = options_into(m);
  ok.library_paths = {lib.path()};
  lib.write("ptest_n32.inc", "#debug \"deep enough\"\n");
  EXPECT_NO_THROW(parse_scene_text("#version 3.7;\n#include \"ptest_n1.inc\"\n", "test.pov", ok));
  EXPECT_EQ(m.joined(), "deep enough");
}

TEST(Limits, MacroCallsInsideIfsAndLoopsDoNotCountAsNesting) {
  // The macro-depth limit counts macro calls only: deep recursion that stays under it works inside #if/#while.
  const std::string text = "#version 3.7;\n#macro Count(N) #if (N > 0) #local I = 0; #while (I < 1) "
                           "#local I = I + 1; Count(N - 1) #end #else #debug \"bottom\" #end #end\nCount(200)\n";
  EXPECT_EQ(debug_output(text), "bottom");
}

// ParseOptions::cancel (povtrace's Ctrl-C): an endless #while stops with a located error once it is set; unset, the
// same scene parses as far as it goes (a bounded loop here).
TEST(Limits, CancelStopsAnEndlessLoop) {
  std::atomic<bool> cancel{true};
  ParseOptions o;
  o.cancel = &cancel;
  const ParseError e = parse_error("#version 3.7;\n#declare I = 0;\n#while (1) #declare I = I + 1; #end\n", o);
  EXPECT_EQ(e.bare_message(), "interrupted while parsing");
  cancel = false;
  EXPECT_NO_THROW(parse_scene_text("#version 3.7;\n#declare I = 0;\n#while (I < 100000) #declare I = I + 1; #end\n",
                                   "test.pov", o));
}

TEST(Robustness, DeeplyNestedCommentsAreFine) {
  const std::string text = "#version 3.7;\n" + repeat("/* ", 100000) + repeat("*/ ", 100000) + "sphere { 0, 1 }\n";
  EXPECT_EQ(parse(text).objects.size(), 1u);
  const ParseError e = parse_error("#version 3.7;\n" + repeat("/* ", 100000) + repeat("*/ ", 99999));
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, 1);
}

}  // namespace
}  // namespace povtrace::test

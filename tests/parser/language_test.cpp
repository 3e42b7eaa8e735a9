// The SDL language features of issue 3 items 2–4 (povray-sdl-and-geometry.md §3–§5): arrays, #switch/#case/
// #range/#break, #declare deprecated, file I/O and its confinement, string comparisons, datetime/now, the
// parse-time object queries inside/min_extent/max_extent, and the camera angle limit. Expected values are POV-Ray
// 3.7.0.10's own output: the verified scenes in /work/shared/docs/semantics-scenes/sdl_*.pov, or `povray` runs
// of the scene quoted in each test.
#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

namespace fs = std::filesystem;

std::string out(const std::string& body) { return debug_output("#version 3.7;\n" + body); }

// The error of `#version 3.7;\n` + body: its line, column and message.
struct Failure {
  int line = 0, column = 0;
  std::string message;
};
Failure failure(const std::string& body, const ParseOptions& options = {}, const std::string& name = "test.pov") {
  const ParseError e = parse_error("#version 3.7;\n" + body, options, name);
  return {e.location().line, e.location().column, e.bare_message()};
}

std::string file_text(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// ---- Arrays -------------------------------------------------------------------------------------------------
TEST(Arrays, DirectivesSceneValues) {
  // sdl_directives.pov, the arrays section.
  EXPECT_EQ(out("#macro P(S, V) #debug concat(S, \" = \", str(V,0,4), \"\\n\") #end\n"
                "#declare A = array[3] {1, 2, 3};\n"
                "#declare B = array[2][3] { {1,2,3}, {4,5,6} };\n"
                "P(\"dimensions(B)\", dimensions(B))\n"
                "P(\"dimension_size(B,1)\", dimension_size(B,1))\n"
                "P(\"dimension_size(B,2)\", dimension_size(B,2))\n"
                "P(\"B[1][2]\", B[1][2])\n"
                "P(\"A[1.9] (truncation)\", A[1.9])\n"
                "#declare E = array[4];\n"
                "#ifdef (E[0]) P(\"E[0] defined\", 1) #else P(\"E[0] undefined\", 0) #end\n"
                "#declare E[0] = 5;\n"
                "#ifdef (E[0]) P(\"E[0] defined after assign\", 1) #end\n"
                "#declare A2 = array[3] {1 2 3};\n"
                "P(\"array without commas A2[2]\", A2[2])\n"),
            "dimensions(B) = 2.0000\ndimension_size(B,1) = 2.0000\ndimension_size(B,2) = 3.0000\nB[1][2] = 6.0000\n"
            "A[1.9] (truncation) = 2.0000\nE[0] undefined = 0.0000\nE[0] defined after assign = 1.0000\n"
            "array without commas A2[2] = 3.0000\n");
}

TEST(Arrays, DimensionSizeOutOfRangeIsZeroAndTruncates) {
  EXPECT_EQ(out("#declare B = array[2][3];\n"
                "#debug concat(str(dimension_size(B,0),0,0), \" \", str(dimension_size(B,3),0,0), \" \", "
                "str(dimension_size(B,2.9),0,0))\n"),
            "0 0 3");
}

TEST(Arrays, AreValuesCopiedByDeclareAndPassedToMacrosByReference) {
  // povray: A0=1 C0=9, then the macro writes through to A.
  EXPECT_EQ(out("#declare A = array[3] {1, 2, 3};\n"
                "#declare C = A;\n#declare C[0] = 9;\n"
                "#debug concat(\"A0=\", str(A[0],0,0), \" C0=\", str(C[0],0,0), \"\\n\")\n"
                "#macro SetFirst(Arr, V) #declare Arr[0] = V; #end\n"
                "SetFirst(A, 7)\n"
                "#debug concat(\"A0 after macro=\", str(A[0],0,0))\n"),
            "A0=1 C0=9\nA0 after macro=7");
}

TEST(Arrays, NestedArraysAreCopiedDeeply) {
  EXPECT_EQ(out("#declare N = array[2] { array[2] {1,2}, array[2] {3,4} };\n"
                "#declare M = N;\n#declare M[1][0] = 30;\n"
                "#debug concat(str(N[1][0],0,0), \" \", str(M[1][0],0,0), \" \", str(dimensions(N[0]),0,0))\n"),
            "3 30 1");
}

TEST(Arrays, LocalOfAnOuterArraysElementHasNoEffectAsInPovRay) {
  // povray: "dims inside=1 A1=2", "L0=5", "top-level local A2=8".
  Messages m;
  parse("#version 3.7;\n#declare A = array[3] {1, 2, 3};\n"
        "#macro LocalSet() #local A[1] = 42; #debug concat(\"A1=\", str(A[1],0,0), \"\\n\") #end\n"
        "LocalSet()\n"
        "#macro LocalOwn() #local L = array[2]; #local L[0] = 5; #debug concat(\"L0=\", str(L[0],0,0), \"\\n\") #end\n"
        "LocalOwn()\n"
        "#local A[2] = 8;\n#debug concat(\"A2=\", str(A[2],0,0))\n",
        &m);
  ASSERT_EQ(m.items.size(), 4u);
  EXPECT_NE(m.items[0].find("test.pov:3:26: warning: #local of an element of 'A'"), std::string::npos) << m.items[0];
  EXPECT_EQ(m.items[1], "A1=2\n");
  EXPECT_EQ(m.items[2], "L0=5\n");
  EXPECT_EQ(m.items[3], "A2=8");
}

TEST(Arrays, ElementsOfEveryTypeWhereAnIdentifierOfThatTypeIsAccepted) {
  // Vectors with postfix and unary minus, strings in string functions and comparisons (povray: "V[1].y=5.0
  // -V[0].z=-3.0", "abcd", "S0<S1").
  EXPECT_EQ(out("#declare V = array[2] {<1,2,3>, <4,5,6>};\n"
                "#debug concat(\"V[1].y=\", str(V[1].y,0,1), \" -V[0].z=\", str(-V[0].z,0,1), \"\\n\")\n"
                "#declare S = array[2] {\"ab\", \"cd\"};\n#debug concat(S[0], S[1], \"\\n\")\n"
                "#if (S[0] < S[1]) #debug \"S0<S1\" #end\n"),
            "V[1].y=5.0 -V[0].z=-3.0\nabcd\nS0<S1");
  // Objects, textures, pigments, finishes and transforms.
  const SceneDescription s =
      parse("#version 3.7;\n"
            "#declare O = array[2] { sphere { 0, 1 }, box { 0, 1 } };\n"
            "#declare T = array[1] { texture { pigment { rgb <1,0,0> } } };\n"
            "#declare P = array[1] { pigment { rgb <0,1,0> } };\n"
            "#declare F = array[1] { finish { phong 0.5 } };\n"
            "#declare M = array[1] { transform { translate x } };\n"
            "object { O[0] texture { T[0] } }\n"
            "object { O[1] pigment { P[0] } finish { F[0] } transform { M[0] } }\n"
            "O[0]\n");
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_TRUE(std::holds_alternative<Sphere>(s.objects[0].shape));
  EXPECT_EQ(s.objects[0].texture->layers.back().pigment.colour.r, 1.0);
  ASSERT_TRUE(std::holds_alternative<Box>(s.objects[1].shape));
  EXPECT_EQ(s.objects[1].texture->layers.back().pigment.colour.g, 1.0);
  EXPECT_EQ(s.objects[1].texture->layers.back().finish.phong, 0.5);
  EXPECT_EQ(s.objects[1].world_from_object.m[3][0], 1.0);
  EXPECT_TRUE(std::holds_alternative<Sphere>(s.objects[2].shape));
}

TEST(Arrays, ElementAsMacroArgumentIsAValue) {
  EXPECT_EQ(out("#declare A = array[2] {1, 2};\n#macro Twice(X) (2*X) #end\n"
                "#debug str(Twice(A[1]),0,0)\n"),
            "4");
}

TEST(Arrays, DefinedOfElements) {
  // povray: "defined N[1][0]=1 N[0][0]=0".
  EXPECT_EQ(out("#declare N = array[2][2];\n#declare N[1][0] = 3;\n"
                "#debug concat(str(defined(N[1][0]),0,0), str(defined(N[0][0]),0,0), str(defined(N),0,0), "
                "str(defined(Nope),0,0))\n"),
            "1010");
}

TEST(Arrays, UndefOfAnElementUnassignsIt) {
  // povray: 01.
  EXPECT_EQ(out("#declare A = array[2]{1,2};\n#undef A[1]\n#debug concat(str(defined(A[1]),0,0), "
                "str(defined(A[0]),0,0))\n"),
            "01");
}

TEST(Arrays, DeclareWithoutSemicolonThenAssign) {
  // The element assignment on the next line runs after the array is stored (povray: E1=5).
  EXPECT_EQ(out("#declare E = array[2]\n#declare E[1] = 5;\n#debug str(E[1],0,0)\n"), "5");
}

TEST(Arrays, ArraysInAnyInitialiserNestingAndDirectivesInside) {
  EXPECT_EQ(out("#declare C = array[2][2][2] { { {1,2},{3,4} }, { {5,6},{7,8} } };\n"
                "#declare D = array[3] { 1, #if (1) 20, #else 30, #end 3 };\n"
                "#debug concat(str(C[1][0][1],0,0), \" \", str(D[1],0,0))\n"),
            "6 20");
}

struct ErrorCase {
  std::string name;
  std::string body;   // after "#version 3.7;\n": line 2 is the body's first line
  int line, column;
  std::string message;
};

class LanguageErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(LanguageErrors, PositionAndMessage) {
  const Failure f = failure(GetParam().body);
  EXPECT_EQ(f.line, GetParam().line) << f.message;
  EXPECT_EQ(f.column, GetParam().column) << f.message;
  EXPECT_EQ(f.message, GetParam().message);
}

INSTANTIATE_TEST_SUITE_P(
    Arrays, LanguageErrors,
    ::testing::Values(
        // povray: "Attempted to redefine float identifier as string identifier." (sdl_eps.pov)
        ErrorCase{"TypeFixedByTheFirstValue", "#declare Arr = array[2] {1, \"x\"}\n", 2, 29,
                  "cannot store a string in this array, an array of floats (the first value stored fixes the "
                  "element type)"},
        // povray: "Attempted to redefine vector identifier as float identifier."
        ErrorCase{"FloatIntoVectors", "#declare V = array[2]{<1,2,3>, 0};\n", 2, 32,
                  "cannot store a float in this array, an array of vectors (the first value stored fixes the "
                  "element type)"},
        ErrorCase{"AssignmentKeepsTheType", "#declare V = array[2]{1, 2};\n#declare V[0] = <1,2,3>;\n", 3, 17,
                  "cannot store a vector in V, an array of floats (the first value stored fixes the element "
                  "type)"},
        // povray: "Attempt to access uninitialized array element."
        ErrorCase{"ReadBeforeAssignment", "#declare A = array[2]; #declare X = A[1];\n", 2, 37,
                  "the array element A[1] is read before any value was assigned to it"},
        // povray: "Array subscript out of range"
        ErrorCase{"SubscriptOutOfRange", "#declare A = array[2]{1,2}; #declare X = A[2];\n", 2, 44,
                  "subscript 2 is out of range for A (dimension 1 has size 2: 0 to 1)"},
        ErrorCase{"SecondSubscriptOutOfRange", "#declare A = array[2][3];\n#declare A[1][3] = 0;\n", 3, 15,
                  "subscript 3 is out of range for A (dimension 2 has size 3: 0 to 2)"},
        // povray: "Negative subscript"
        ErrorCase{"NegativeSubscript", "#declare A = array[2]{1,2}; #declare X = A[-0.5];\n", 2, 44,
                  "negative subscript -0.5 for A"},
        // povray: "Expected '[', ; found instead"
        ErrorCase{"TooFewSubscripts", "#declare A = array[2][2]; #declare X = A[1];\n", 2, 44,
                  "expected '[' : A has 2 dimensions and takes as many subscripts, found ';'"},
        ErrorCase{"TooFewInitialisers", "#declare A = array[2]{1};\n", 2, 24,
                  "too few initialisers: dimension 1 of this array has size 2, found 1"},
        // povray: "No matching } in '{', float function 'float constant' found instead"
        ErrorCase{"TooManyInitialisers", "#declare A = array[2]{1,2,3};\n", 2, 27,
                  "expected '}' closing the array initialiser opened at test.pov:2:22 (dimension 1 has size 2), "
                  "found the number 3"},
        // povray: "Invalid dimension size for an array"
        ErrorCase{"ZeroSize", "#declare A = array[0];\n", 2, 20, "an array dimension must be at least 1, found 0"},
        // povray: "Too many array dimensions"
        ErrorCase{"SixDimensions", "#declare A = array[1][1][1][1][1][1];\n", 2, 34,
                  "an array has at most 5 dimensions"},
        ErrorCase{"ElementOfAnUndeclaredArray", "#declare A[1] = 2;\n", 2, 11,
                  "expected '=' after #declare A, found '['"},
        ErrorCase{"ArrayInAnExpression", "#declare A = array[1]{1};\n#declare B = A + 1;\n", 3, 16,
                  "expected an object, light_source, camera, background, global_settings or a directive, found "
                  "'+'"},
        ErrorCase{"DimensionsOfANonArray", "#declare X = dimensions(1);\n", 2, 25,
                  "expected an array identifier in dimensions(), found the number 1"}),
    [](const auto& p) { return p.param.name; });

// ---- #switch, #case, #range, #break --------------------------------------------------------------------------
TEST(Switch, DirectivesSceneFallThroughRangeAndElse) {
  // sdl_directives.pov and sdl_eps.pov.
  EXPECT_EQ(out("#macro P(S, V) #debug concat(S, \" = \", str(V,0,4), \"\\n\") #end\n"
                "#switch (2)\n  #case (1) P(\"case1\", 1)\n  #case (2) P(\"case2\", 2)\n"
                "  #case (3) P(\"case3 (fallthrough)\", 3)\n  #break\n  #case (4) P(\"case4\", 4)\n"
                "  #else P(\"else\", 5)\n#end\n"
                "#switch (7.5)\n  #range (5, 10) P(\"range 5..10\", 7.5) #break\n  #else P(\"switch else\", 0)\n#end\n"
                "#switch (99)\n  #case (1) P(\"c1\", 1) #break\n  #else P(\"switch else taken\", 99)\n#end\n"
                "#switch (1 + 0.5e-10) #case (1) #debug \"#case uses eps equality\\n\" #break #end\n"),
            "case2 = 2.0000\ncase3 (fallthrough) = 3.0000\nrange 5..10 = 7.5000\nswitch else taken = 99.0000\n"
            "#case uses eps equality\n");
}

TEST(Switch, ElseAfterAMatchedCaseFallsThroughAsInPovRay37) {
  // povray 3.7.0.10 prints a, b, c, d, e, g, h: #else does not stop a matched section, and a #case after #else
  // is reached by falling through.
  EXPECT_EQ(out("#switch (1) #case (1) #debug \"a\" #else #debug \"b\" #end\n"
                "#switch (1) #case (1) #debug \"c\" #case (2) #debug \"d\" #range (5,6) #debug \"e\" #end\n"
                "#switch (3) #case (1) #debug \"f\" #else #debug \"g\" #case (3) #debug \"h\" #end\n"),
            "abcdegh");
}

TEST(Switch, RangeBoundsAreInclusiveAndNestedSwitchesAreSkipped) {
  EXPECT_EQ(out("#switch (5)\n #case (1)\n  #switch (1) #case (1) #debug \"inner\" #end\n"
                " #range (5, 5) #debug \"lo\"\n#end\n"
                "#switch (10) #range (5, 10) #debug \"hi\" #end\n"
                "#switch (10.5) #range (5, 10) #debug \"no\" #end\n"),
            "lohi");
}

TEST(Break, LeavesTheSwitchOnlyInsideALoop) {
  // povray: two, three — #break leaves the #switch, not the #while around it.
  EXPECT_EQ(out("#declare I = 0;\n#while (I < 5)\n  #switch (I)\n  #case (2) #debug \"two \" #break\n"
                "  #case (3) #debug \"three\"\n  #end\n  #declare I = I + 1;\n#end\n"),
            "two three");
}

TEST(Break, LeavesWhileAndForThroughAnIf) {
  // sdl_misc.pov: "#break left the #while at I=3".
  EXPECT_EQ(out("#declare I = 0;\n#while (1)\n  #declare I = I + 1;\n  #if (I >= 3) #break #end\n#end\n"
                "#debug concat(\"#break left the #while at I=\", str(I,0,0), \"\\n\")\n"
                "#for (J, 1, 10) #if (J = 4) #break #else #debug str(J,0,0) #end #end\n"
                "#debug concat(\" J=\", str(J,0,0))\n"),
            "#break left the #while at I=3\n123 J=4");
}

TEST(Break, ReturnsFromTheCurrentMacro) {
  // povray: m1 (then #break), m1 m2.
  EXPECT_EQ(out("#macro M(X) #debug \"m1 \" #if (X) #break #end #debug \"m2 \" #end\n"
                "M(1) M(0)\n#declare I = 0;\n#while (I < 2) M(1) #declare I = I + 1; #end\n#debug \"done\"\n"),
            "m1 m1 m2 m1 m1 done");
}

INSTANTIATE_TEST_SUITE_P(
    Switch, LanguageErrors,
    ::testing::Values(
        // povray: "Invalid context for #break"
        ErrorCase{"BreakOutside", "#break\n", 2, 2, "#break outside a #switch, #while, #for or macro"},
        // povray: "Mis-matched '#case' or '#range'."
        ErrorCase{"CaseOutside", "#case (1)\n", 2, 2, "#case without a matching #switch"},
        ErrorCase{"RangeOutside", "#if (1) #range (1, 2) #end\n", 2, 10, "#range without a matching #switch"},
        ErrorCase{"SwitchWithoutCase", "#switch (1) #debug \"x\" #case (1) #end\n", 2, 14,
                  "expected #case or #range after #switch, found the keyword 'debug'"},
        ErrorCase{"RangeNeedsTwoBounds", "#switch (1) #range (1) #end\n", 2, 22,
                  "expected ',' between the bounds of #range (Low, High), found ')'"},
        ErrorCase{"UnterminatedSwitch", "#switch (2) #case (1)\n", 2, 2, "this #switch has no matching #end"}),
    [](const auto& p) { return p.param.name; });

// ---- #declare deprecated --------------------------------------------------------------------------------------
TEST(Deprecated, LaterReadsWarnOnceOrEveryTime) {
  // povray (the same scene): "line 5: use New instead", "line 6: D2 is old" twice, "line 7: Identifier 'D3' was
  // declared deprecated.", and nothing for the second Old nor for #ifdef.
  Messages m;
  parse("#version 3.7;\n"
        "#declare deprecated once \"use New instead\" Old = 1;\n"
        "#declare deprecated \"D2 is old\" D2 = 2;\n"
        "#declare deprecated D3 = 3;\n"
        "#declare X = Old + 0;\n"
        "#declare X = Old + D2 + D2;\n"
        "#declare X = D3;\n"
        "#ifdef (D2) #debug \"ifdef does not warn\" #end\n",
        &m);
  ASSERT_EQ(m.items.size(), 5u) << m.joined();
  EXPECT_EQ(m.items[0], "test.pov:5:14: warning: use New instead\n#declare X = Old + 0;\n             ^");
  EXPECT_EQ(m.items[1], "test.pov:6:20: warning: D2 is old\n#declare X = Old + D2 + D2;\n                   ^");
  EXPECT_EQ(m.items[2], "test.pov:6:25: warning: D2 is old\n#declare X = Old + D2 + D2;\n                        ^");
  EXPECT_EQ(m.items[3],
            "test.pov:7:14: warning: Identifier 'D3' was declared deprecated.\n#declare X = D3;\n             ^");
  EXPECT_EQ(m.items[4], "ifdef does not warn");
}

TEST(Deprecated, TargetsOfDeclareAndUndefWarnToo) {
  // povray: "line 3: old A", "line 4: old A", "line 7: old B" — nothing for #ifdef nor defined().
  Messages m;
  parse("#version 3.7;\n#declare deprecated \"old A\" A = 1;\n#declare A = 2;\n#undef A\n#ifdef (A) #end\n"
        "#declare deprecated \"old B\" B = array[2];\n#declare B[0] = 1;\n#declare X = defined(B);\n",
        &m);
  ASSERT_EQ(m.items.size(), 3u) << m.joined();
  EXPECT_EQ(m.items[0].substr(0, 31), "test.pov:3:10: warning: old A\n#");
  EXPECT_EQ(m.items[1].substr(0, 30), "test.pov:4:8: warning: old A\n#");
  EXPECT_EQ(m.items[2].substr(0, 31), "test.pov:7:10: warning: old B\n#");
}

TEST(Deprecated, TheValueIsUsable) {
  const SceneDescription s = parse("#version 3.7;\n#declare deprecated once \"old\" T = texture { pigment { rgb 1 } }\n"
                                   "sphere { 0, 1 texture { T } }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(s.objects[0].texture->layers.back().pigment.colour.r, 1.0);
}

TEST(Deprecated, GlassOldIncludeParses) {
  // glass_old.inc declares its textures `deprecated once` (32 sample scenes include it through glass.inc).
  if (!fs::exists(fs::path(kStandardIncludeDir) / "glass_old.inc")) GTEST_SKIP() << "no POV-Ray include directory";
  Messages m;
  parse("#version 3.7;\n#include \"glass_old.inc\"\n#declare A = T_Glass1;\n#declare B = T_Glass1;\n", &m);
  ASSERT_EQ(m.items.size(), 1u) << m.joined();
  EXPECT_NE(m.items[0].find("warning: See notes in glass_old.inc regarding use of this deprecated texture: "
                            "T_Glass1"),
            std::string::npos);
}

// ---- File I/O -----------------------------------------------------------------------------------------------
TEST(FileIo, RoundTripAndReadingToTheEnd) {
  // sdl_fileio.pov.
  ScratchFolder dir;
  WorkingDirectory here(dir.path());
  Messages m;
  parse_scene_text("#version 3.7;\n"
                   "#fopen F \"sdl_fileio_data.txt\" write\n"
                   "#write (F, 1.5, \",\", <1,2,3>, \",\", \"\\\"str\\\"\", \"\\n\")\n"
                   "#fclose F\n"
                   "#fopen G \"sdl_fileio_data.txt\" read\n"
                   "#read (G, A, V, S)\n"
                   "#fclose G\n"
                   "#debug concat(\"read back: A=\", str(A,0,2), \" V=\", vstr(3,V,\",\",0,1), \" S=\", S, \"\\n\")\n"
                   "#fopen H \"sdl_fileio_data.txt\" read\n"
                   "#declare N = 0;\n"
                   "#while (defined(H))\n  #read (H, Item)\n  #declare N = N + 1;\n#end\n"
                   "#fclose H\n"
                   "#debug concat(\"items until EOF (loop count) = \", str(N,0,0), \"\\n\")\n",
                   "main.pov", options_into(m));
  EXPECT_EQ(m.joined(), "read back: A=1.50 V=1.0,2.0,3.0 S=str\nitems until EOF (loop count) = 3\n");
  EXPECT_EQ(file_text(dir / "sdl_fileio_data.txt"), "1.5,<1,2,3> ,\"str\"\n");
}

TEST(FileIo, WriteFormatsRawIntegersAndAppend) {
  // The bytes povray writes for the same directives.
  ScratchFolder dir;
  WorkingDirectory here(dir.path());
  parse_scene_text("#version 3.7;\n#fopen F \"out.txt\" write\n"
                   "#write (F, 1.5, 2, <1,2>, <1,2,3>, <1,2,3,4>, <1,0.5,0,0.25,1>, \"s\\n\", 1e-7, \" \", "
                   "123456789, \"\\n\")\n"
                   "#write (F, uint8 65, uint8 <66,67>, sint16le 258, sint16be 258, uint8 300, sint8 -200, \"\\n\")\n"
                   "#fclose F\n#fopen F \"out.txt\" append\n"
                   "#write (F, -2.5, \",\", \"\\\"q\\\\n\\\"\", \",\", <-1,-2,-3>, \",\")\n#fclose F\n",
                   "main.pov", {});
  EXPECT_EQ(file_text(dir / "out.txt"),
            std::string("1.52<1,2> <1,2,3> <1,2,3,4> <1,0.5,0,0.25,1> s\n1e-07 1.23457e+08\nABC\x02\x01\x01\x02\xff\x80"
                        "\n-2.5,\"q\\n\",<-1,-2,-3> ,"));
}

TEST(FileIo, ReadsSignedNumbersVectorsAndStrings) {
  ScratchFolder dir;
  dir.write("data.txt", "-2.5, +3, <-1, 2 -3>, \"q\\n\" /* comments are skipped */, <1,2,3,4,5>\n");
  WorkingDirectory here(dir.path());
  Messages m;
  parse_scene_text("#version 3.7;\n#fopen F \"data.txt\" read\n#read (F, A, B, V, S, C)\n"
                   "#debug concat(str(A,0,1), \" \", str(B,0,1), \" \", vstr(3,V,\",\",0,0), \" \", S, "
                   "str(C.transmit,0,0), \" \", str(defined(F),0,0))\n",
                   "main.pov", options_into(m));
  EXPECT_EQ(m.joined(), "-2.5 3.0 -1,2,-3 q\n5 0");
}

TEST(FileIo, ATokenAfterAnItemThatIsNoCommaIsDropped) {
  // povray reads 1.0, drops `foo`, then fails on the ',' (data file line 1).
  ScratchFolder dir;
  dir.write("d.txt", "1 foo, 2\n");
  WorkingDirectory here(dir.path());
  Messages m;
  ParseOptions o = options_into(m);
  try {
    parse_scene_text("#version 3.7;\n#fopen G \"d.txt\" read\n#while (defined(G))\n  #read (G, It)\n"
                     "  #debug concat(str(It,0,1), \"\\n\")\n#end\n",
                     "main.pov", o);
    FAIL() << "the ',' must be refused";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.location().file_name(), (fs::current_path() / "d.txt").string());
    EXPECT_EQ(e.location().line, 1);
    EXPECT_EQ(e.location().column, 6);
    EXPECT_EQ(e.bare_message(), "expected a float, a vector or a string literal in the data file \"d.txt\"");
  }
  EXPECT_EQ(m.joined(), "1.0\n");
}

TEST(FileIo, ArrayElementsAsTargetsAndUnknownNamesBecomeGlobals) {
  ScratchFolder dir;
  dir.write("d.txt", "4, 5, 6");
  WorkingDirectory here(dir.path());
  Messages m;
  parse_scene_text("#version 3.7;\n#declare A = array[2];\n"
                   "#macro R() #fopen F \"d.txt\" read #read (F, A[1], A[0], G) #end\nR()\n"
                   "#debug concat(str(A[0],0,0), str(A[1],0,0), str(G,0,0), str(defined(F),0,0))\n",
                   "main.pov", options_into(m));
  EXPECT_EQ(m.joined(), "5460");
}

TEST(FileIo, ConfinedToTheScenesAndTheWorkingDirectory) {
  ScratchFolder scene_dir, cwd, elsewhere;
  const fs::path scene = scene_dir.write("scene.pov", "");
  WorkingDirectory here(cwd.path());
  const auto parse_file = [&](const std::string& text) {
    std::ofstream(scene, std::ios::binary) << "#version 3.7;\n" << text;
    ParseOptions o;
    o.message_sink = [](const std::string&) {};
    return parse_scene(scene, o);
  };
  // Writing beside the scene file (by its absolute path) and in the working directory (relative) is allowed.
  parse_file("#fopen F \"" + (scene_dir / "a.txt").string() + "\" write #write (F, 1) #fclose F\n"
             "#fopen F \"sub/../b.txt\" write #write (F, 2) #fclose F\n");
  EXPECT_EQ(file_text(scene_dir / "a.txt"), "1");
  EXPECT_EQ(file_text(cwd / "b.txt"), "2");
  // Anywhere else is an error naming the path.
  const fs::path outside = fs::weakly_canonical(elsewhere / "c.txt");
  for (const std::string& name : {outside.string(), std::string("../") + elsewhere.path().filename().string() +
                                                        "/c.txt"}) {
    try {
      parse_file("#fopen F \"" + name + "\" write\n");
      ADD_FAILURE() << name << " was opened";
    } catch (const ParseError& e) {
      EXPECT_EQ(e.location().line, 2);
      EXPECT_EQ(e.location().column, 10);
      EXPECT_NE(e.bare_message().find("the file \"" + name + "\" (" + outside.string() + ") is outside the scene's "
                                      "directory"),
                std::string::npos)
          << e.bare_message();
    }
  }
  EXPECT_FALSE(fs::exists(elsewhere / "c.txt"));
  // A symbolic link inside that points outside is resolved and refused too, for reading as for writing.
  elsewhere.write("secret.txt", "1");
  fs::create_symlink(elsewhere / "secret.txt", cwd / "link.txt");
  try {
    parse_file("#fopen F \"link.txt\" read\n");
    ADD_FAILURE() << "the link was followed";
  } catch (const ParseError& e) {
    EXPECT_NE(e.bare_message().find("is outside the scene's directory"), std::string::npos) << e.bare_message();
  }
  fs::create_symlink(elsewhere / "missing.txt", cwd / "dangling.txt");
  try {
    parse_file("#fopen F \"dangling.txt\" write\n");
    ADD_FAILURE() << "the dangling link was written through";
  } catch (const ParseError& e) {
    EXPECT_NE(e.bare_message().find("symbolic link"), std::string::npos) << e.bare_message();
  }
  EXPECT_FALSE(fs::exists(elsewhere / "missing.txt"));
}

TEST(FileIo, Errors) {
  ScratchFolder dir;
  dir.write("d.txt", "1");
  WorkingDirectory here(dir.path());
  const auto f = [](const std::string& body) { return failure(body, {}, "main.pov"); };
  Failure e = f("#fopen F \"d.txt\" read\n#write (F, 1)\n");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 9);
  EXPECT_EQ(e.message, "cannot write to \"d.txt\": it is open for reading");
  e = f("#fopen F \"w.txt\" write\n#read (F, X)\n");
  EXPECT_EQ(e.line, 3);
  EXPECT_EQ(e.column, 8);
  EXPECT_EQ(e.message, "cannot read from \"w.txt\": it is open for writing");
  e = f("#read (Nothing, X)\n");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 8);
  EXPECT_EQ(e.message, "expected a file identifier opened by #fopen … read, found the undeclared identifier 'Nothing'");
  e = f("#fopen F \"missing.txt\" read\n");
  EXPECT_EQ(e.line, 2);
  EXPECT_EQ(e.column, 10);
  EXPECT_NE(e.message.find("cannot open the user file \"missing.txt\" for reading"), std::string::npos) << e.message;
  e = f("#fopen F \"d.txt\" modify\n");
  EXPECT_EQ(e.column, 18);
  EXPECT_EQ(e.message, "expected read, write or append after the file name, found the undeclared identifier 'modify'");
  // #fclose of a file that was read to its end (no longer defined) is ignored, as POV-Ray does.
  EXPECT_EQ(debug_output("#version 3.7;\n#fopen F \"d.txt\" read\n#read (F, X)\n#fclose F\n#debug str(X,0,0)\n"), "1");
}

// ---- Strings -------------------------------------------------------------------------------------------------
TEST(Strings, ComparisonsInConditions) {
  // sdl_eps.pov ("string compare works") and povray runs: eq, ne, ge.
  EXPECT_EQ(out("#if (\"abc\" < \"abd\") #debug \"lt \" #end\n#if (\"abc\" = \"abc\") #debug \"eq \" #end\n"
                "#if (\"abc\" != \"abd\") #debug \"ne \" #end\n#if (\"b\" >= \"abc\") #debug \"ge \" #end\n"
                "#if (\"b\" <= \"abc\") #debug \"le \" #end\n#if (\"ab\" > \"a\") #debug \"gt \" #end\n"
                "#declare S = \"x\";\n#debug str((S = \"x\") + (concat(S, \"y\") = \"xy\") * 10, 0, 0)\n"),
            "lt eq ne ge gt 11");
}

TEST(Strings, StrcmpIsTheCharacterDifference) {
  // povray: strcmp("a","c") = -2, strcmp("abc","ab") = 99.
  EXPECT_EQ(out("#debug concat(str(strcmp(\"a\",\"c\"),0,0), \" \", str(strcmp(\"abc\",\"ab\"),0,0), \" \", "
                "str(strcmp(\"q\",\"q\"),0,0))\n"),
            "-2 99 0");
}

TEST(Strings, DatetimeAndNow) {
  // povray: "2000-01-01 00:00:00Z|2000/01/02 12".
  EXPECT_EQ(out("#debug concat(datetime(0), \"|\", datetime(1.5, \"%Y/%m/%d %H\"))\n"),
            "2000-01-01 00:00:00Z|2000/01/02 12");
  const double days = eval_float("now");
  const double expected =
      (std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count() - 946684800.0) /
      86400.0;
  EXPECT_NEAR(days, expected, 1.0 / 24);
  EXPECT_EQ(out("#declare T = now;\n#debug datetime(T, \"%Y\")\n").size(), 4u);
}

INSTANTIATE_TEST_SUITE_P(
    Strings, LanguageErrors,
    ::testing::Values(ErrorCase{"StringNeedsAComparison", "#if (\"a\" + \"b\") #end\n", 2, 10,
                                "expected a comparison operator (<, <=, =, !=, >=, >) after a string, found '+'"},
                      ErrorCase{"EmptyDatetimeFormat", "#declare S = datetime(0, \"\");\n", 2, 26,
                                "datetime() needs a non-empty format string"}),
    [](const auto& p) { return p.param.name; });

// ---- directives met while looking for an operator (§1 item 6) ---------------------------------------------------
TEST(OperatorLook, DirectivesAfterAnOperandRunOutsideDeclaresAndConditions) {
  // povray 3.7.0.10 prints these lines for the same scene: in an expression of #debug, an object or a transform, a
  // directive ahead of a complete operand (here the #else of the macro's #if, then the macro's #end) runs, and the
  // expression goes on with `* 2` in the caller (advanced/isocacti.pov's `pigment { Rand_Array_Item(…) * … }`).
  EXPECT_EQ(out("#macro M6() #if (1) 2 #else 3 #end #end\n"
                "#debug concat(str(M6() * 2, 0, 3), \"\\n\")\n"
                "#declare S = sphere { 0, M6() * 0.5 }\n"
                "#debug concat(vstr(3, max_extent(S), \",\", 0, 3), \"\\n\")\n"
                "#declare T = sphere { 0, 1 translate <M6() * 2, 0, 0> }\n"
                "#debug concat(vstr(3, max_extent(T), \",\", 0, 3), \"\\n\")\n"),
            "4.000\n1.000,1.000,1.000\n5.000,1.000,1.000\n");
}

INSTANTIATE_TEST_SUITE_P(
    OperatorLook, LanguageErrors,
    ::testing::Values(
        // povray: "All #declares of float, vector, and color require semicolon" at the macro's '#else': in the
        // number of a #declare the '#' is a plain token (Ok_To_Declare off).
        ErrorCase{"DirectiveAfterTheNumberOfADeclare",
                  "#macro M6() #if (1) 2 #else 3 #end #end\n#declare V = M6() * 0.5;\n", 2, 23,
                  "expected ';' after the value of V, found '#'"},
        // povray: "Expected ')', # found instead" (Parse_Cond_Param keeps the raw look too).
        ErrorCase{"DirectiveAfterAnOperandOfACondition",
                  "#macro M6() #if (1) 2 #else 3 #end #end\n#if (M6() * 2 > 3) #end\n", 3, 11,
                  "expected ')' closing the condition, found '*'"}),
    [](const auto& p) { return p.param.name; });

// ---- inside, min_extent, max_extent ------------------------------------------------------------------------------
TEST(ObjectQueries, ExtentsAsPovRayComputesThem) {
  // Every line is povray's output for the same scene: single-precision boxes, a tight box around a sphere moved by a
  // similarity, the 8-corner box otherwise, ±1e10 for planes and for unions wider than 1e6.
  EXPECT_EQ(out("#macro V(S, P) #debug concat(S, \" \", vstr(3, P, \",\", 0, 9), \"\\n\") #end\n"
                "#declare S1 = sphere { <1,2,3>, 0.1 };\nV(\"s1 min\", min_extent(S1)) V(\"s1 max\", max_extent(S1))\n"
                "#declare S2 = sphere { 0, 1 scale <1,2,3> translate x };\n"
                "V(\"s2 min\", min_extent(S2)) V(\"s2 max\", max_extent(S2))\n"
                "#declare S3 = sphere { <1,0,0>, 1 rotate z*45 scale 2 };\n"
                "V(\"s3 min\", min_extent(S3)) V(\"s3 max\", max_extent(S3))\n"
                "#declare S4 = sphere { 0, 1 scale <1,2,1> rotate z*30 };\n"
                "V(\"s4 min\", min_extent(S4)) V(\"s4 max\", max_extent(S4))\n"
                "#declare B1 = box { <-1,-2,-3>, <1,2,3> rotate y*30 translate 0.3 };\n"
                "V(\"b1 min\", min_extent(B1)) V(\"b1 max\", max_extent(B1))\n"
                "#declare B2 = box { 0, 1 scale -2 };\nV(\"b2 min\", min_extent(B2)) V(\"b2 max\", max_extent(B2))\n"
                "#declare P1 = plane { y, 1 };\nV(\"p1 min\", min_extent(P1)) V(\"p1 max\", max_extent(P1))\n"
                "#declare U1 = union { sphere { 0, 1 } box { <0,0,0>, <3,0.5,0.5> } translate y };\n"
                "V(\"u1 min\", min_extent(U1)) V(\"u1 max\", max_extent(U1))\n"
                "#declare U2 = union { sphere { 0, 1 } plane { y, 0 } };\n"
                "V(\"u2 min\", min_extent(U2)) V(\"u2 max\", max_extent(U2))\n"),
            "s1 min 0.899999976,1.899999976,2.900000095\ns1 max 1.100000024,2.099999905,3.100000143\n"
            "s2 min 0.000000000,-2.000000000,-3.000000000\ns2 max 2.000000000,2.000000000,3.000000000\n"
            "s3 min -0.585786462,-0.585786462,-2.000000000\ns3 max 3.414213657,3.414213657,2.000000000\n"
            "s4 min -1.866025448,-2.232050896,-1.000000000\ns4 max 1.866025448,2.232050896,1.000000000\n"
            "b1 min -2.066025496,-1.700000048,-2.798076153\nb1 max 2.666025400,2.299999952,3.398076057\n"
            "b2 min -2.000000000,-2.000000000,-2.000000000\nb2 max 0.000000000,0.000000000,0.000000000\n"
            "p1 min -10000000000.000000000,-10000000000.000000000,-10000000000.000000000\n"
            "p1 max 10000000000.000000000,10000000000.000000000,10000000000.000000000\n"
            "u1 min -1.000000000,0.000000000,-1.000000000\nu1 max 3.000000000,2.000000000,1.000000000\n"
            "u2 min -10000000000.000000000,-10000000000.000000000,-10000000000.000000000\n"
            "u2 max 10000000000.000000000,10000000000.000000000,10000000000.000000000\n");
}

TEST(ObjectQueries, TorusExtentsAsPovRayComputesThem) {
  // povray's output: Torus::Compute_BBox, the box of radius R + r and height r carried by the whole transform; in a
  // union, the union of the children's boxes.
  EXPECT_EQ(out("#declare T = torus { 2, 0.5 rotate <30, 20, 10> scale <1, 2, 0.5> translate <0.3, 0.1, -1> }\n"
                "#declare U = union { torus { 1, 0.25 } sphere { <3,0,0>, 0.5 } }\n"
                "#debug concat(vstr(3, min_extent(T), \",\", 0, 9), \" \", vstr(3, max_extent(T), \",\", 0, 9), \"\\n\")\n"
                "#debug concat(vstr(3, min_extent(U), \",\", 0, 9), \" \", vstr(3, max_extent(U), \",\", 0, 9), \"\\n\")\n"),
            "-2.968861341,-3.803291798,-2.562233925 3.568861246,4.003291607,0.562233686\n"
            "-1.250000000,-0.500000000,-1.250000000 3.500000000,0.500000000,1.250000000\n");
}

TEST(ObjectQueries, ConeCylinderDiscExtentsAsPovRayComputesThem) {
  // povray's output for the same scene: Cone::Compute_Cone_Data / Compute_Cylinder_Data (the first end point is the
  // apex, the wider end turned to z = 1) and Disc::Compute_BBox, carried by Compute_Coordinate_Transform and the
  // object's transforms; the corners in Recompute_BBox's order (c1's y minimum is +0 there).
  EXPECT_EQ(out("#macro V(S, P) #debug concat(S, \" \", vstr(3, P, \",\", 0, 9), \"\\n\") #end\n"
                "#declare C1 = cylinder { <0,0,0>, <0,1,0>, 0.5 };\n"
                "V(\"c1 min\", min_extent(C1)) V(\"c1 max\", max_extent(C1))\n"
                "#declare C2 = cylinder { <0,0,0>, <1,1,1>, 0.3 open rotate 20*y translate x };\n"
                "V(\"c2 min\", min_extent(C2)) V(\"c2 max\", max_extent(C2))\n"
                "#declare C3 = cylinder { <1,2,3>, <1,2,-3>, 0.25 };\n"
                "V(\"c3 min\", min_extent(C3)) V(\"c3 max\", max_extent(C3))\n"
                "#declare K1 = cone { <0,0,0>, 0.1, <1,2,3>, 1 };\n"
                "V(\"k1 min\", min_extent(K1)) V(\"k1 max\", max_extent(K1))\n"
                "#declare K2 = cone { <1,0,0>, 0, <-1,1,0.5>, 0.7 scale <1,2,3> };\n"
                "V(\"k2 min\", min_extent(K2)) V(\"k2 max\", max_extent(K2))\n"
                "#declare K3 = cone { <0,0,0>, 0.5, <0,0,-2>, 0.5 };\n"
                "V(\"k3 min\", min_extent(K3)) V(\"k3 max\", max_extent(K3))\n"
                "#declare D1 = disc { <0,0,0>, <1,2,3>, 1.5, 0.5 rotate 30*x };\n"
                "V(\"d1 min\", min_extent(D1)) V(\"d1 max\", max_extent(D1))\n"
                "#declare U1 = union { cone { 0, 1, y, 0 } disc { 2*x, z, 1 } };\n"
                "V(\"u1 min\", min_extent(U1)) V(\"u1 max\", max_extent(U1))\n"),
            "c1 min -0.500000000,0.000000000,-0.500000000\n"
            "c1 max 0.500000000,1.000000000,0.500000000\n"
            "c2 min 0.718092203,-0.300000012,-0.384758711\n"
            "c2 max 2.563620567,1.299999952,0.982431173\n"
            "c3 min 0.750000000,1.750000000,-3.000000000\n"
            "c3 max 1.250000000,2.250000000,3.000000000\n"
            "k1 min -1.039643288,-0.920713484,-0.801783741\n"
            "k1 max 2.039643288,2.920713425,3.801783800\n"
            "k2 min -1.481101036,-1.618898988,-2.749545336\n"
            "k2 max 1.481101036,3.618899345,4.249545097\n"
            "k3 min -0.500000000,-0.500000000,-2.000000000\n"
            "k3 max 0.500000000,0.500000000,0.000000000\n"
            "d1 min -1.559732199,-1.591449380,-0.470903873\n"
            "d1 max 1.559732199,1.591449380,0.470903873\n"
            "u1 min -1.000000000,-1.000000000,-1.000000000\n"
            "u1 max 3.000000000,1.000000000,1.000000000\n");
}

TEST(ObjectQueries, InsideAsPovRayTestsIt) {
  // povray's output for the same scene: strict sphere, closed box, plane with its surface inside, inverses,
  // union, difference (the hole's surface is outside), intersection, merge.
  EXPECT_EQ(out("#macro F(S, X) #debug concat(S, \" \", str(X, 0, 0), \"\\n\") #end\n"
                "#declare S1 = sphere { <1,2,3>, 0.1 };\n"
                "F(\"in s1 centre\", inside(S1, <1,2,3>)) F(\"in s1 surface\", inside(S1, <1.1,2,3>))\n"
                "#declare S2 = sphere { 0, 1 scale <1,2,3> translate x };\n"
                "F(\"in s2\", inside(S2, <1,1.9,0>)) F(\"out s2\", inside(S2, <1.9,1.9,0>))\n"
                "#declare BX = box{-1,1};\nF(\"in box corner\", inside(BX, <1,1,1>))\n"
                "#declare IB = box { -1, 1 inverse };\n"
                "F(\"inv box corner\", inside(IB, <1,1,1>)) F(\"inv box out\", inside(IB, <2,1,1>))\n"
                "#declare IS = sphere { 0, 1 inverse };\n"
                "F(\"inv sphere surface\", inside(IS, <1,0,0>)) F(\"inv sphere out\", inside(IS, <2,0,0>))\n"
                "#declare P1 = plane { y, 1 };\n"
                "F(\"plane below\", inside(P1, <0,0.5,0>)) F(\"plane on\", inside(P1, <5,1,0>)) "
                "F(\"plane above\", inside(P1, <0,1.5,0>))\n"
                "#declare P2 = plane { <0,2,0>, 1 scale 2 rotate x*90 };\n"
                "F(\"p2 a\", inside(P2, <0,0,1.9>)) F(\"p2 b\", inside(P2, <0,0,2.1>))\n"
                "#declare IP = plane { y, 1 inverse };\n"
                "F(\"inv plane on\", inside(IP, <0,1,0>)) F(\"inv plane below\", inside(IP, <0,0.5,0>))\n"
                "#declare U1 = union { sphere { 0, 1 } box { <0,0,0>, <3,0.5,0.5> } translate y };\n"
                "F(\"u1 in\", inside(U1, <2,1.2,0.2>)) F(\"u1 out\", inside(U1, <2,2,0.2>))\n"
                "#declare D1 = difference { box { -1, 1 } sphere { 0, 0.5 } };\n"
                "F(\"d1 hole\", inside(D1, <0,0,0>)) F(\"d1 wall\", inside(D1, <0.8,0,0>)) "
                "F(\"d1 hole surface\", inside(D1, <0.5,0,0>))\n"
                "#declare I1 = intersection { box { -1, 1 } sphere { 0, 1.2 } };\n"
                "F(\"i1 corner\", inside(I1, <0.9,0.9,0.9>)) F(\"i1 mid\", inside(I1, <0.9,0,0>))\n"
                "#declare M1 = merge { sphere { 0, 1 } sphere { x, 1 } };\nF(\"m1\", inside(M1, <1.5,0,0>))\n"),
            "in s1 centre 1\nin s1 surface 0\nin s2 1\nout s2 0\nin box corner 1\ninv box corner 0\ninv box out 1\n"
            "inv sphere surface 0\ninv sphere out 1\nplane below 1\nplane on 1\nplane above 0\np2 a 1\np2 b 0\n"
            "inv plane on 1\ninv plane below 0\nu1 in 1\nu1 out 0\nd1 hole 0\nd1 wall 1\nd1 hole surface 0\n"
            "i1 corner 0\ni1 mid 1\nm1 1\n");
}

TEST(ObjectQueries, ElementsAndQueriesInConditions) {
  EXPECT_EQ(out("#declare O = array[1] { sphere { 0, 2 } };\n"
                "#if (inside(O[0], <1,1,1>) & max_extent(O[0]).x = 2) #debug \"yes\" #end\n"),
            "yes");
}

INSTANTIATE_TEST_SUITE_P(
    ObjectQueries, LanguageErrors,
    ::testing::Values(
        // povray: "Object identifier expected."
        ErrorCase{"InsideNeedsAnObjectIdentifier", "#declare X = inside(box { 0, 1 }, 0);\n", 2, 21,
                  "expected an object identifier in inside(), found the keyword 'box'"},
        // Without the renderer's geometry (this parser-only test), a height field's samples are not read.
        ErrorCase{"HeightFieldWithoutGeometry",
                  "#declare H = height_field { function 4, 4 { x } }\n#declare X = max_extent(H);\n", 3, 25,
                  "unsupported: max_extent() of a height_field (its samples are read by the renderer) is a POV-Ray "
                  "feature that povtrace does not render yet"},
        // A union's box, made when the union is made and carried, is lost to the clip's; the refusal names why.
        ErrorCase{"ExtentOfAUnionClippedByAHeightFieldWithoutGeometry",
                  "#declare U = union { sphere { 0, 1 } sphere { x, 1 } clipped_by { height_field { function 4, 4 { x } } } "
                  "rotate 10*y }\n#declare X = min_extent(U);\n",
                  3, 25,
                  "unsupported: min_extent() of a height_field (its samples are read by the renderer) is a POV-Ray "
                  "feature that povtrace does not render yet"},
        ErrorCase{"Trace", "#declare S = sphere { 0, 1 }\n#declare P = trace(S, <0,0,-5>, z);\n", 3, 14,
                  "unsupported: the function 'trace' is a POV-Ray feature that povtrace does not render yet"}),
    [](const auto& p) { return p.param.name; });

// ---- Camera angle ----------------------------------------------------------------------------------------------
// POV-Ray 3.5+ (Parse_Camera, only_mods): a declared camera is final. `camera { C }` is C as it is (its angle,
// look_at and orthographic resize are not applied again), and only transforms may follow the identifier. POV-Ray
// renders templates/Basic_Scenes/Orthographic_isometric.pov's declared orthographic camera like the inline one.
TEST(CameraIdentifier, IsFinalAndTakesOnlyTransforms) {
  const std::string items = "orthographic angle 15 location <20,20,-20> right x*4/3 look_at <0,0.5,0>";
  const Camera direct = parse("#version 3.7;\ncamera { " + items + " }\n").camera;
  const std::string declared = "#version 3.7;\n#declare C = camera { " + items + " }\n";
  const Camera used = parse(declared + "camera { C }\n").camera;
  const Camera moved = parse(declared + "camera { C translate <1,2,3> }\n").camera;
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(used.right[i], direct.right[i]);
    EXPECT_EQ(used.up[i], direct.up[i]);
    EXPECT_EQ(used.direction[i], direct.direction[i]);
    EXPECT_EQ(used.location[i], direct.location[i]);
    EXPECT_EQ(moved.right[i], direct.right[i]);
    EXPECT_DOUBLE_EQ(moved.location[i], direct.location[i] + (i + 1.0));
  }
  EXPECT_EQ(failure(declared + "camera { C angle 30 }\n").column, 12);
}

TEST(CameraAngle, TheLimitOf180HoldsForPerspectiveAndOrthographicOnly) {
  // fisheye and the other projections take up to 360°.
  for (const std::string camera : {"camera { fisheye angle 360 }", "camera { ultra_wide_angle angle 270 }",
                                    "camera { spherical angle 360, 180 }", "camera { cylinder 1 angle 200 }"})
    EXPECT_NO_THROW(parse("#version 3.7;\n" + camera + "\n")) << camera;
  EXPECT_EQ(failure("camera { orthographic angle 180 }\n").message,
            "the camera angle must be less than 180 degrees for a perspective or orthographic camera");
  const Failure negative = failure("camera { angle -1 }\n");
  EXPECT_EQ(negative.column, 10);
  EXPECT_EQ(negative.message, "the camera angle must not be negative");
  // An angle of 0 is ignored, as by POV-Ray.
  const Camera c = parse("#version 3.7;\ncamera { direction <0,0,2> angle 0 }\n").camera;
  EXPECT_EQ(c.direction.z, 2.0);
}

}  // namespace
}  // namespace povtrace::test

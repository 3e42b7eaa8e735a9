// Language directives (povray-sdl-and-geometry.md §3–§4): scope of #declare/#local, conditionals with skipped
// junk, loops, macros (recursion, alias parameters, textual splicing), #include search, #version, #undef, #error.
// Expected outputs are POV-Ray 3.7's (semantics-scenes/sdl_directives.pov, sdl_scope.pov, or checked with povray).
#include <string>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

// A #version 3.7 scene with the P(label, value) macro that prints "label=value" (4 decimals) on a line.
std::string run(const std::string& body) {
  return debug_output("#version 3.7;\n#macro P(S, V) #debug concat(S, \"=\", str(V,0,4), \"\\n\") #end\n" + body);
}

struct DirectiveCase {
  std::string name;
  std::string body;
  std::string expected;   // the #debug output
};

class Directive : public ::testing::TestWithParam<DirectiveCase> {};

TEST_P(Directive, PrintsWhatPovRayPrints) { EXPECT_EQ(run(GetParam().body), GetParam().expected); }

// ---- #declare / #local scope ------------------------------------------------------------------------------------
INSTANTIATE_TEST_SUITE_P(
    Scope, Directive,
    ::testing::Values(
        DirectiveCase{"LocalShadowsGlobalInsideAMacro",
                      "#declare G = 1;\n#macro M1() #local G = 100; P(\"in\", G) #end\nM1()\nP(\"after\", G)\n",
                      "in=100.0000\nafter=1.0000\n"},
        DirectiveCase{"DeclareInMacroWritesTheGlobal",
                      "#declare G = 1;\n#macro M2() #declare G = 2; #end\nM2()\nP(\"G\", G)\n", "G=2.0000\n"},
        DirectiveCase{"DeclareOverwritesTheVisibleLocal",
                      "#declare G = 2;\n#macro M3() #local G = 50; #declare G = 60; P(\"in\", G) #end\nM3()\n"
                      "P(\"after\", G)\n",
                      "in=60.0000\nafter=2.0000\n"},
        DirectiveCase{"DeclareInMacroCreatesAGlobalLocalsDie",
                      "#macro MakeX() #declare MadeX = 7; #local NotMade = 8; #end\nMakeX()\nP(\"MadeX\", MadeX)\n"
                      "#ifdef (NotMade) P(\"NotMade\", 1) #else P(\"NotMade undefined\", 0) #end\n",
                      "MadeX=7.0000\nNotMade undefined=0.0000\n"},
        DirectiveCase{"DynamicScope",
                      "#macro Outer() #local V = 1; Inner() #end\n#macro Inner() P(\"V\", V) #end\nOuter()\n"
                      "#ifndef (V) P(\"gone\", 0) #end\n",
                      "V=1.0000\ngone=0.0000\n"},
        DirectiveCase{"LocalAtTopLevelIsGlobal",
                      "#local TopLocal = 1;\n#macro Get() TopLocal #end\nP(\"TopLocal\", Get())\n",
                      "TopLocal=1.0000\n"},
        DirectiveCase{"RetypingIsAllowed",
                      "#declare X = 1;\n#declare X = \"now a string\";\n#debug concat(X, \"\\n\")\n"
                      "#declare X = <1,2,3>;\nP(\"X.z\", X.z)\n",
                      "now a string\nX.z=3.0000\n"},
        DirectiveCase{"PredeclaredIdentifiersAreOrdinaryGlobals",
                      "P(\"frame_number\", frame_number)\n#declare image_width = 5;\nP(\"w\", image_width)\n",
                      "frame_number=0.0000\nw=5.0000\n"}),
    [](const auto& p) { return p.param.name; });

// ---- Conditionals ----------------------------------------------------------------------------------------------
INSTANTIATE_TEST_SUITE_P(
    Conditionals, Directive,
    ::testing::Values(
        DirectiveCase{"IfElseIfElse",
                      "#declare K = 2;\n#if (K = 1) P(\"if\", 1) #elseif (K = 2) P(\"elseif\", 2) #else "
                      "P(\"else\", 3) #end\n",
                      "elseif=2.0000\n"},
        DirectiveCase{"ElseTaken", "#if (0) P(\"if\", 1) #elseif (0) P(\"elseif\", 2) #else P(\"else\", 3) #end\n",
                      "else=3.0000\n"},
        DirectiveCase{"FirstBranchSkipsTheRest",
                      "#if (1) P(\"if\", 1) #elseif (1/0 junk ) P(\"elseif\", 2) #else P(\"else\", 3) #end\n",
                      "if=1.0000\n"},
        DirectiveCase{"ConditionIsTrueAboveTheEpsilon",
                      "#if (1e-11) P(\"tiny\", 1) #else P(\"zero\", 0) #end\n#if (1e-9) P(\"small\", 1) #end\n",
                      "zero=0.0000\nsmall=1.0000\n"},
        // A skipped branch is lexed but not parsed: junk tokens, undeclared names, bad syntax are fine.
        DirectiveCase{"SkippedBranchMayHoldJunk",
                      "#if (0)\n } } ) @ $ 1.5 Undeclared \"str\" sphere { #declare = ; <<<\n#else P(\"ok\", 1) "
                      "#end\n",
                      "ok=1.0000\n"},
        DirectiveCase{"NestedBlocksInASkippedBranch",
                      "#if (0)\n #if (1) P(\"a\", 1) #else P(\"b\", 2) #end\n #while (1) #end\n #macro Q() #end\n"
                      "#else P(\"outer else\", 3) #end\n",
                      "outer else=3.0000\n"},
        DirectiveCase{"IfdefIfndef",
                      "#declare D = 1;\n#ifdef (D) P(\"D\", 1) #end\n#ifdef (Nope) P(\"Nope\", 1) #else "
                      "P(\"no Nope\", 0) #end\n#ifndef (Nope) P(\"ifndef\", 1) #end\n#ifdef (sphere) P(\"kw\", 1) "
                      "#end\n",
                      "D=1.0000\nno Nope=0.0000\nifndef=1.0000\n"},
        DirectiveCase{"DefinedFunction", "#declare G = 1;\nP(\"G\", defined(G))\nP(\"H\", defined(H))\n",
                      "G=1.0000\nH=0.0000\n"},
        DirectiveCase{"DirectiveInsideAVector",
                      "#declare V = <1,\n#if (1) 2, #else 3, #end\n 3>;\nP(\"V.y\", V.y)\n", "V.y=2.0000\n"}),
    [](const auto& p) { return p.param.name; });

// ---- Loops -------------------------------------------------------------------------------------------------------
INSTANTIATE_TEST_SUITE_P(
    Loops, Directive,
    ::testing::Values(
        DirectiveCase{"While",
                      "#declare I = 0; #declare Sum = 0;\n#while (I < 5) #declare Sum = Sum + I; #declare I = I + 1; "
                      "#end\nP(\"sum\", Sum) P(\"I\", I)\n",
                      "sum=10.0000\nI=5.0000\n"},
        DirectiveCase{"WhileFalseFromTheStart", "#while (0) P(\"never\", 1) #end\nP(\"done\", 1)\n", "done=1.0000\n"},
        DirectiveCase{"NestedWhile",
                      "#declare I = 0; #declare N = 0;\n#while (I < 3) #declare J = 0; #while (J < 4) "
                      "#declare N = N + 1; #declare J = J + 1; #end #declare I = I + 1; #end\nP(\"N\", N)\n",
                      "N=12.0000\n"},
        DirectiveCase{"ForEndsOnTheFirstValuePastTheEnd",
                      "#declare Sum = 0;\n#for (J, 1, 10, 3) #declare Sum = Sum + J; #end\nP(\"sum\", Sum)\n"
                      "P(\"J\", J)\n",
                      "sum=22.0000\nJ=13.0000\n"},
        DirectiveCase{"ForFractionalStepIncludesTheEnd",
                      "#declare N = 0;\n#for (J, 0, 1, 0.1) #declare N = N + 1; #end\nP(\"count\", N)\n",
                      "count=11.0000\n"},
        DirectiveCase{"ForNegativeStep",
                      "#declare Sum = 0;\n#for (J, 5, 1, -2) #declare Sum = Sum + J; #end\nP(\"sum\", Sum) "
                      "P(\"J\", J)\n",
                      "sum=9.0000\nJ=-1.0000\n"},
        DirectiveCase{"ForDefaultStepAndEmptyRange",
                      "#declare N = 0;\n#for (I, 1, 3) #declare N = N + I; #end\n#for (K, 5, 1) P(\"never\", 1) "
                      "#end\nP(\"N\", N) P(\"K\", K)\n",
                      "N=6.0000\nK=5.0000\n"}),
    [](const auto& p) { return p.param.name; });

// ---- Macros ---------------------------------------------------------------------------------------------------
INSTANTIATE_TEST_SUITE_P(
    Macros, Directive,
    ::testing::Values(
        DirectiveCase{"AliasParameterWritesThroughWithDeclare",
                      "#declare Q = 10;\n#macro Inc(V) #declare V = V + 1; #end\nInc(Q)\nP(\"Q\", Q)\n",
                      "Q=11.0000\n"},
        DirectiveCase{"AliasParameterWritesThroughWithLocal",
                      "#declare Q = 10;\n#macro IncL(A) #local A = A + 1; #end\nIncL(Q)\nP(\"Q\", Q)\n", "Q=11.0000\n"},
        DirectiveCase{"ExpressionArgumentIsByValue",
                      "#declare Q = 10;\n#macro Inc(V) #declare V = V + 1; #end\nInc(Q+0)\nP(\"Q\", Q)\n",
                      "Q=10.0000\n"},
        DirectiveCase{"AliasOfACallersLocal",
                      "#macro Inc(V) #declare V = V + 1; #end\n#macro Outer() #local L = 1; Inc(L) P(\"L\", L) #end\n"
                      "Outer()\n",
                      "L=2.0000\n"},
        DirectiveCase{"BodyIsSplicedAsText", "#macro Add(A,B) A+B #end\nP(\"2*Add(1,2)\", 2*Add(1,2))\n",
                      "2*Add(1,2)=4.0000\n"},
        DirectiveCase{"ParenthesisedBody", "#macro Sq(A) (A*A) #end\nP(\"Sq(3)+1\", Sq(3)+1)\n", "Sq(3)+1=10.0000\n"},
        // #declare runs a macro call that starts the value itself (call_macros_ahead): the value reads on after the
        // body, a body may start with another call or a directive, or be empty (checked with povray).
        DirectiveCase{"DeclareOfAValueStartingWithAMacroCall",
                      "#macro Add(A,B) A+B #end\n#macro Two() Add(1,1) #end\n#macro Nothing() #end\n"
                      "#macro Loc() #local T = 4; T #end\n#declare X = Add(1,2)*2;\n#declare Y = Two() + 1;\n"
                      "#declare Z = Nothing() 7;\n#declare W = Loc();\n#declare V = Add(<1,2,3>, 1);\n"
                      "P(\"X\", X) P(\"Y\", Y) P(\"Z\", Z) P(\"W\", W) P(\"Vy\", V.y)\n",
                      "X=5.0000\nY=3.0000\nZ=7.0000\nW=4.0000\nVy=3.0000\n"},
        DirectiveCase{"Recursion",
                      "#macro Fact(N) #local R = 1; #if (N > 1) #local R = N*Fact(N-1); #end R #end\n"
                      "P(\"Fact(5)\", Fact(5))\n",
                      "Fact(5)=120.0000\n"},
        DirectiveCase{"ArgumentCommasAreOptional", "#macro Add(A,B) A+B #end\nP(\"sum\", Add(1 2))\n",
                      "sum=3.0000\n"},
        DirectiveCase{"MacroProducingAString",
                      "#macro Name() \"made\" #end\n#declare S = Name();\n#debug concat(S, \"\\n\")\n", "made\n"},
        DirectiveCase{"MacroRedefinition",
                      "#macro F() 1 #end\n#macro F() 2 #end\nP(\"F\", F())\n", "F=2.0000\n"}),
    [](const auto& p) { return p.param.name; });

// ---- #version, #undef, #debug/#warning -----------------------------------------------------------------------
INSTANTIATE_TEST_SUITE_P(
    Misc, Directive,
    ::testing::Values(
        DirectiveCase{"VersionIsReadBack",
                      "P(\"v\", version)\n#version 3.5;\nP(\"v\", version)\n#version 3.1;\nP(\"v\", version)\n",
                      "v=3.7000\nv=3.5000\nv=3.1000\n"},
        DirectiveCase{"SemicolonOptionalBefore35", "#version 3.1;\n#declare X = 1\n#declare Y = 2\nP(\"XY\", X+Y)\n",
                      "XY=3.0000\n"},
        DirectiveCase{"SemicolonOptionalForStringsAndObjects",
                      "#declare S = \"abc\"\n#declare O = sphere { 0, 1 }\n#debug concat(S, \"\\n\")\n", "abc\n"},
        DirectiveCase{"Undef", "#declare Z1 = 3; #undef Z1\n#ifndef (Z1) P(\"undefined\", 1) #end\n",
                      "undefined=1.0000\n"},
        DirectiveCase{"UndefUncoversTheOuterValue",
                      "#declare X = 1;\n#macro M() #local X = 2; #undef X P(\"X\", X) #end\nM()\n", "X=1.0000\n"},
        DirectiveCase{"DirectiveWordAfterSpaces", "#   debug \"spaced\\n\"\n", "spaced\n"}),
    [](const auto& p) { return p.param.name; });

// ---- The optional ';' after non-numeric values ----------------------------------------------------------------
// Looking for the optional ';' (or for a second texture block, or an operator after a value) must not run the
// directive that follows before the current #declare is finished (POV-Ray's Ok_To_Declare; all of these parse in
// povray 3.7).
INSTANTIATE_TEST_SUITE_P(
    NoSemicolon, Directive,
    ::testing::Values(
        DirectiveCase{"ObjectThenStatement",
                      "#declare S = sphere { 0, 1 }\n#debug \"after\\n\"\nobject { S }\n", "after\n"},
        DirectiveCase{"TextureUsedByTheNextDeclare",
                      "#declare T = texture { pigment { rgb 1 } }\n#declare U = texture { T }\n"
                      "#ifdef (U) P(\"U\", 1) #end\n",
                      "U=1.0000\n"},
        DirectiveCase{"ObjectUsedByTheNextDeclare",
                      "#declare A = sphere { 0, 1 translate x }\n#declare B = object { A rotate y*90 }\n"
                      "#ifdef (B) P(\"B\", 1) #end\n",
                      "B=1.0000\n"},
        DirectiveCase{"StringUsedByTheNextDeclare",
                      "#declare Str = \"abc\"\n#declare Str2 = concat(Str, \"d\")\n#debug concat(Str2, \"\\n\")\n",
                      "abcd\n"},
        DirectiveCase{"LocalObjectAtTheEndOfAMacroStaysLocal",
                      "#macro M() #local O = sphere { 0, 1 } #end\nM()\n#ifdef (O) P(\"leaked\", 1) #else "
                      "P(\"local\", 0) #end\n",
                      "local=0.0000\n"},
        DirectiveCase{"StringMacroResultThenSemicolon",
                      "#macro Name() \"made\" #end\n#declare S = Name();\n#debug concat(S, \"\\n\")\n", "made\n"},
        DirectiveCase{"MacroResultAsAMacroArgument",
                      "#macro Fact(N) #local R = 1; #if (N > 1) #local R = N*Fact(N-1); #end R #end\n"
                      "P(\"Fact(4)+1\", Fact(4)+1)\n#declare F = Fact(3);\nP(\"F\", F)\n",
                      "Fact(4)+1=25.0000\nF=6.0000\n"},
        DirectiveCase{"FloatsWithoutSemicolonBefore35",
                      "#version 3.1;\n#declare X = 1\n#declare Y = X + 1\nP(\"XY\", X*10+Y)\n", "XY=12.0000\n"},
        DirectiveCase{"LayeredTextureThenDirective",
                      "#declare T = texture { pigment { rgb 1 } } texture { pigment { rgbt 1 } }\n#declare N = 2;\n"
                      "P(\"N\", N)\n",
                      "N=2.0000\n"}),
    [](const auto& p) { return p.param.name; });

TEST(Directives, DeclaredObjectsWithoutSemicolonsBuildTheScene) {
  const SceneDescription s = parse(
      "#version 3.7;\n"
      "#declare T = texture { pigment { rgb <1,0,0> } }\n"
      "#declare U = texture { T finish { phong 1 } }\n"
      "#declare S = sphere { 0, 1 texture { U } }\n"
      "object { S translate x }\n"
      "sphere { 0, 2 }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].texture->layers.back().pigment.colour.r, 1);
  EXPECT_EQ(s.objects[0].texture->layers.back().finish.phong, 1);
  EXPECT_EQ(std::get<Sphere>(s.objects[1].shape).radius, 2);
}

TEST(Directives, VersionGivenOnlyWhenFirst) {
  EXPECT_TRUE(parse("#version 3.7;\nsphere { 0, 1 }\n").version_given);
  EXPECT_EQ(parse("#version 3.6;\n").language_version, 360);
  const SceneDescription none = parse("sphere { 0, 1 }\n");
  EXPECT_FALSE(none.version_given);
  EXPECT_EQ(none.language_version, 370);
  const SceneDescription late = parse("sphere { 0, 1 }\n#version 3.7;\n");
  EXPECT_FALSE(late.version_given);
}

TEST(Directives, UndefOfAnUnknownNameOnlyWarns) {
  Messages m;
  parse("#version 3.7;\n#undef Nothing\n", &m);
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_NE(m.items[0].find("test.pov:2:8: warning: #undef of 'Nothing'"), std::string::npos) << m.items[0];
}

TEST(Directives, WarningGoesToTheSinkWithItsPosition) {
  Messages m;
  parse("#version 3.7;\n  #warning \"careful\"\n", &m);
  ASSERT_EQ(m.items.size(), 1u);
  EXPECT_EQ(m.items[0].rfind("test.pov:2:4: warning: careful", 0), 0u) << m.items[0];
}

TEST(Directives, DeclaresFromOptionsArePredeclared) {
  Messages m;
  ParseOptions o = options_into(m);
  o.declares = {{"Quality", 9}};
  o.image_width = 320;
  parse_scene_text("#version 3.7;\n#debug concat(str(Quality,0,0), \" \", str(image_width,0,0))\n", "o.pov", o);
  EXPECT_EQ(m.joined(), "9 320");
}

TEST(Directives, ErrorAbortsWithItsPosition) {
  const ParseError e = parse_error("#version 3.7;\n#declare A = 1;\n  #error concat(\"stop \", str(A,0,0))\nsphere{0,1}");
  EXPECT_EQ(e.location().line, 3);
  EXPECT_EQ(e.location().column, 4);   // the directive word
  EXPECT_EQ(e.bare_message(), "#error: stop 1");
}

TEST(Directives, DebugInsideAMacroInsideALoop) {
  EXPECT_EQ(debug_output("#version 3.7;\n#macro Say(N) #debug str(N,0,0) #end\n#for (I, 1, 4) Say(I) #end\n"),
            "1234");
}

// ---- #include -------------------------------------------------------------------------------------------------
TEST(Include, FoundOnTheLibraryPathWithItsLocalsDying) {
  ScratchFolder lib;
  lib.write("ptest_scope.inc",
            "#local IncLocal = 5;\n#declare IncGlobal = IncLocal + 1;\n#macro IncMacro() IncGlobal #end\n");
  Messages m;
  ParseOptions o = options_into(m);
  o.library_paths = {lib.path()};
  parse_scene_text(
      "#version 3.7;\n#include \"ptest_scope.inc\"\n"
      "#ifdef (IncLocal) #debug \"visible\\n\" #else #debug \"not visible\\n\" #end\n"
      "#debug concat(str(IncGlobal,0,0), \" \", str(IncMacro(),0,0), \"\\n\")\n",
      "main.pov", o);
  EXPECT_EQ(m.joined(), "not visible\n6 6\n");
}

TEST(Include, AddsDotIncToABareName) {
  ScratchFolder lib;
  lib.write("ptest_bare.inc", "#declare FromInc = 1;\n");
  lib.write("ptest_bare", "#declare FromBare = 1;\n");
  Messages m;
  ParseOptions o = options_into(m);
  o.library_paths = {lib.path()};
  parse_scene_text("#version 3.7;\n#include \"ptest_bare\"\n#debug str(defined(FromInc) + 2*defined(FromBare),0,0)\n",
                   "main.pov", o);
  EXPECT_EQ(m.joined(), "1");
}

TEST(Include, TheWorkingDirectoryIsSearchedFirst) {
  ScratchFolder cwd, lib;
  cwd.write("ptest_which.inc", "#declare Which = 1;\n");
  lib.write("ptest_which.inc", "#declare Which = 2;\n");
  lib.write("ptest_only_lib.inc", "#declare OnlyLib = 3;\n");
  Messages m;
  ParseOptions o = options_into(m);
  o.library_paths = {lib.path()};
  WorkingDirectory here(cwd.path());
  parse_scene_text("#version 3.7;\n#include \"ptest_which.inc\"\n#include \"ptest_only_lib.inc\"\n"
                   "#debug concat(str(Which,0,0), str(OnlyLib,0,0))\n",
                   "main.pov", o);
  EXPECT_EQ(m.joined(), "13");
}

TEST(Include, LibraryPathsInOrderAndNestedIncludes) {
  ScratchFolder first, second;
  second.write("ptest_order.inc", "#declare Order = 2;\n");
  first.write("ptest_order.inc", "#declare Order = 1;\n#include \"ptest_nested.inc\"\n");
  second.write("ptest_nested.inc", "#declare Nested = Order + 10;\n");
  Messages m;
  ParseOptions o = options_into(m);
  o.library_paths = {first.path(), second.path()};
  parse_scene_text("#version 3.7;\n#include \"ptest_order.inc\"\n#debug str(Nested,0,0)\n", "main.pov", o);
  EXPECT_EQ(m.joined(), "11");
}

TEST(Include, FromAFileOnDisk) {
  ScratchFolder dir;
  const auto scene = dir.write("scene.pov", "#version 3.7;\n#include \"ptest_disk.inc\"\nsphere { 0, R }\n");
  dir.write("ptest_disk.inc", "#declare R = 2.5;\n");
  ParseOptions o;
  o.library_paths = {dir.path()};
  const SceneDescription s = parse_scene(scene, o);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(std::get<Sphere>(s.objects[0].shape).radius, 2.5);
  EXPECT_EQ(*s.objects[0].loc.file, scene.string());
  EXPECT_EQ(s.objects[0].loc.line, 3);
}

TEST(Include, ObjectsFromAnIncludeKeepTheirFile) {
  ScratchFolder lib;
  const auto inc = lib.write("ptest_obj.inc", "\n  sphere { 0, 1 }\n");
  ParseOptions o;
  o.library_paths = {lib.path()};
  const SceneDescription s = parse_scene_text("#version 3.7;\n#include \"ptest_obj.inc\"\n", "main.pov", o);
  ASSERT_EQ(s.objects.size(), 1u);
  EXPECT_EQ(*s.objects[0].loc.file, inc.string());
  EXPECT_EQ(s.objects[0].loc.line, 2);
  EXPECT_EQ(s.objects[0].loc.column, 3);
}

TEST(Include, TheSceneFilesDirectoryIsNotSearched) {
  // POV-Ray looks in the working directory and the library paths, not beside the scene file.
  ScratchFolder scene_dir, elsewhere;
  const auto scene = scene_dir.write("scene.pov", "#version 3.7;\n#include \"ptest_beside.inc\"\n");
  scene_dir.write("ptest_beside.inc", "#declare Beside = 1;\n");
  WorkingDirectory here(elsewhere.path());
  ParseOptions o;
  o.message_sink = [](const std::string&) {};
  try {
    parse_scene(scene, o);
    ADD_FAILURE() << "the include beside the scene file was found";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.location().file_name(), scene.string());
    EXPECT_EQ(e.location().line, 2);
    EXPECT_NE(e.bare_message().find("cannot find include file \"ptest_beside.inc\""), std::string::npos);
  }
}

TEST(Include, StandardIncludeDirectoryIsSearched) {
  // The standard include directory is appended automatically (colors.inc, with its #switch, parses).
  if (!std::filesystem::exists(std::filesystem::path(kStandardIncludeDir) / "colors.inc"))
    GTEST_SKIP() << "no POV-Ray include directory";
  EXPECT_EQ(debug_output("#version 3.7;\n#include \"colors.inc\"\n#debug vstr(3, Red, \",\", 0, 0)\n"), "1,0,0");
}

}  // namespace
}  // namespace povtrace::test

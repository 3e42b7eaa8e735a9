// function { pigment { … } } through the renderer's pigment code (scene/pattern_evaluator.hpp,
// renderer/pattern_evaluator.cpp). The expected values are POV-Ray 3.7.0.10's own: the same scene lines run
// through `povray -D +W16 +H16 -F` printed them with vstr(5, F(P.x, P.y, P.z), ",", 0, 9) and
// str(F(P.x, P.y, P.z).gray, 0, 9), so they are compared to within their last printed digit, except where
// turbulence or a map blends: POV-Ray blends in single precision and povtrace in double (rounded to single after),
// which differ by up to about 6e-8.
#include <array>
#include <cstdlib>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "renderer/pattern_evaluator.hpp"
#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

ParseOptions with_pigments(Messages& messages) {
  ParseOptions o = options_into(messages);
  o.pattern_evaluator = std::make_shared<render::RendererPatterns>();
  return o;
}

// r, g, b, filter, transmit and gray of F(P), F declared by `declaration`, as #debug prints them.
std::array<double, 6> colour_at(const std::string& declaration, const std::string& point) {
  Messages m;
  parse_scene_text("#version 3.7;\n" + declaration + "\n#declare P = " + point +
                       ";\n#debug concat(vstr(5, F(P.x, P.y, P.z), \" \", 0, 16), \" \", "
                       "str(F(P.x, P.y, P.z).gray, 0, 16), \"\\n\")\n",
                   "pigment.pov", with_pigments(m));
  std::array<double, 6> v{};
  if (m.items.empty()) {
    ADD_FAILURE() << "no output for " << declaration;
    return v;
  }
  std::istringstream in(m.items.back());
  for (double& c : v) in >> c;
  return v;
}

struct Case {
  const char* pigment;
  const char* point;
  std::array<double, 6> povray;   // r, g, b, filter, transmit, gray
  double tolerance = 1e-9;
};

TEST(PigmentFunction, ColoursAreThePigmentColoursPovRayPrints) {
  const Case cases[] = {
      {"gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] }", "<0.3,0,0>",
       {0.699999988, 0, 0.300000012, 0, 0, 0.242099998}},
      {"rgbft <0.2,0.4,0.6,0.1,0.3>", "<0.3,0,0>", {0.200000003, 0.400000006, 0.600000024, 0.100000001, 0.300000012, 0.363400007}},
      {"checker rgb <1,1,0> rgbf <0,0.5,1,0.5> scale 0.5", "<0.3,0.1,0.2>", {1, 1, 0, 0, 0, 0.886}},
      {"checker rgb <1,1,0> rgbf <0,0.5,1,0.5> scale 0.5", "<0.7,0.1,0.2>", {0, 0.5, 1, 0.5, 0, 0.4085}},
      {"bozo turbulence 0.5 color_map { [0 rgb 0] [0.5 rgbt <1,0.5,0,0.5>] [1 rgb <0,0,1>] } scale 0.3",
       "<0.3,0.1,0.2>", {0.494981706, 0.247490853, 0, 0, 0.247490853, 0.292781679}, 1e-7},
      {"bozo turbulence 0.5 color_map { [0 rgb 0] [0.5 rgbt <1,0.5,0,0.5>] [1 rgb <0,0,1>] } scale 0.3",
       "<1.7,-0.4,2.2>", {0.871354103, 0.435677052, 0.128645867, 0, 0.435677052, 0.530071581}, 1e-7},
      {"wood turbulence 0.1 color_map { [0 rgb <0.8,0.5,0.2>] [1 rgb <0.3,0.1,0>] } rotate <10,20,30> "
       "warp { turbulence 0.3 }",
       "<0.35,0.6,-1.2>", {0.405746341, 0.184597045, 0.042298526, 0, 0, 0.234056355}, 1e-7},
      {"granite pigment_map { [0 rgb 1] [1 gradient y color_map {[0 rgb 0][1 rgb <0,1,0>]}] }", "<0.35,0.6,-1.2>",
       {0.741124272, 0.896449745, 0.741124272, 0, 0, 0.832610976}, 1e-7},
      {"crackle color_map { [0 rgb 0] [1 rgb 1] }", "<0.35,0.6,-1.2>",
       {0.194370136, 0.194370136, 0.194370136, 0, 0, 0.194370136}},
  };
  const char* names[] = {"red", "green", "blue", "filter", "transmit", "gray"};
  for (const Case& c : cases) {
    const std::array<double, 6> v =
        colour_at(std::string("#declare F = function { pigment { ") + c.pigment + " } }", c.point);
    for (int i = 0; i < 6; ++i) EXPECT_NEAR(v[i], c.povray[i], c.tolerance) << c.pigment << " at " << c.point << " " << names[i];
  }
}

TEST(PigmentFunction, MembersAreReadInsideOtherFunctions) {
  Messages m;
  parse_scene_text(
      "#version 3.7;\n"
      "#declare F1 = function { pigment { gradient x color_map { [0 rgb <1,0,0>] [1 rgb <0,0,1>] } } }\n"
      "#declare F4 = function { pigment { bozo turbulence 0.5 color_map { [0 rgb 0] [0.5 rgbt <1,0.5,0,0.5>] "
      "[1 rgb <0,0,1>] } scale 0.3 } }\n"
      "#declare G = function { F1(x,y,z).green + F1(x,y,z).blue * 2 + F4(x,y,z).gray }\n"
      "#debug concat(str(G(0.3, 0.1, 0.2), 0, 16), \"\\n\")\n",
      "pigment.pov", with_pigments(m));
  ASSERT_FALSE(m.items.empty());
  EXPECT_NEAR(std::strtod(m.items.back().c_str(), nullptr), 0.8927817030251026, 1e-7);   // bozo's blend
}

TEST(PigmentFunction, WithoutAnEvaluatorOnlyAPlainColourIsEvaluated) {
  Messages m;
  parse_scene_text("#version 3.7;\n#declare F = function { pigment { rgb <0.2, 0.4, 0.6> } }\n"
                   "#debug concat(str(F(0, 0, 0).green, 0, 3), \"\\n\")\n",
                   "pigment.pov", options_into(m));
  ASSERT_FALSE(m.items.empty());
  EXPECT_EQ(m.items.back(), "0.400\n");
  const ParseError e = parse_error("#declare F = function { pigment { bozo } }\n#declare V = F(1, 2, 3).red;\n",
                                   options_into(m));
  EXPECT_EQ(e.location().line, 2);
  EXPECT_NE(e.bare_message().find("unsupported: the pigment function (written at test.pov:1:14)"), std::string::npos)
      << e.bare_message();
}

TEST(PigmentFunction, WhatTheRendererCannotEvaluateIsRefusedByName) {
  Messages m;
  const ParseError e = parse_error(
      "#declare F = function { pigment { uv_mapping checker rgb 0 rgb 1 } }\n#declare V = F(1, 2, 3).red;\n",
      with_pigments(m));
  EXPECT_EQ(e.location().line, 2);
  EXPECT_NE(e.bare_message().find("unsupported: uv_mapping (a pigment function has no surface, so no u, v) (at test.pov:1:25) in "
                                  "the pigment function (written at test.pov:1:14)"),
            std::string::npos)
      << e.bare_message();
}

TEST(PigmentFunction, ShapesThatEvaluateItWhileRenderingAcceptIt) {
  Messages m;
  const SceneDescription s = parse_scene_text(
      "#version 3.7;\n#declare F = function { pigment { bumps color_map { [0 rgb 0] [1 rgb 1] } scale 0.2 } }\n"
      "isosurface { function { y - F(x, 0, z).gray } contained_by { box { -1, 1 } } }\n"
      "height_field { function 8, 8 { F(x, y, z).red } }\n"
      "plane { y, 0 pigment { function { F(x, y, z).blue } } }\n",
      "test.pov", with_pigments(m));
  ASSERT_EQ(s.objects.size(), 3u);
  for (const Object& o : s.objects) EXPECT_FALSE(o.unsupported) << o.unsupported->name;
}

}  // namespace
}  // namespace povtrace::test

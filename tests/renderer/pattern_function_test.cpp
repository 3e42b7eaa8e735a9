// function { pattern { … } } through the renderer's pattern code (scene/pattern_evaluator.hpp,
// renderer/pattern_evaluator.cpp). The expected values are POV-Ray 3.7.0.10's own: the same scene lines run
// through `povray -D +W16 +H16 -F` printed them with str(F(P.x, P.y, P.z), 0, 16).
#include <cstdlib>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "renderer/pattern_evaluator.hpp"
#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

ParseOptions with_patterns(Messages& messages) {
  ParseOptions o = options_into(messages);
  o.pattern_evaluator = std::make_shared<render::RendererPatterns>();
  return o;
}

// F(P) as #debug prints it with 16 decimals, F declared by `declaration` (`#declare F = …`).
double value_at(const std::string& declaration, const std::string& point) {
  Messages m;
  parse_scene_text("#version 3.7;\n" + declaration + "\n#declare P = " + point +
                       ";\n#debug concat(str(F(P.x, P.y, P.z), 0, 16), \"\\n\")\n",
                   "pattern.pov", with_patterns(m));
  if (m.items.empty()) {
    ADD_FAILURE() << "no output for " << declaration;
    return 0;
  }
  return std::strtod(m.items.back().c_str(), nullptr);
}

struct Case {
  const char* pattern;
  const char* point;
  double povray;
};

TEST(PatternFunction, ValuesAreThePatternValuesPovRayPrints) {
  const char* p1 = "<1.37,-0.83,2.11>";
  const char* p2 = "<-2.5,0.45,-0.77>";
  const Case cases[] = {
      {"bozo scale 0.3", p1, 0.5746371875687726},
      {"checker", "<0.5,0.5,1.5>", 1.0},
      {"hexagon", "<0.9,0,0.1>", 0.0},
      {"hexagon", "<1.5,0,0.6>", 2.0},   // list patterns skip the wave step: hexagon's third cell is 2
      {"brick", "<0.2,0.2,0.2>", 1.0},
      {"agate", p1, 0.5356262498310724},
      {"granite", p2, 0.5655361978182744},
      {"crackle", p1, 0.5025549246859538},
      {"wood", p1, 0.7963970509000284},
      {"marble turbulence 0.8 scale 0.5", p2, 0.5571583770160267},
      {"leopard", p1, 0.1344675503072921},
      {"onion", p2, 0.6543172380105586},
      {"spiral1 5", p1, 0.9433774148622245},
      {"bozo turbulence 0.5 scale 0.4 rotate <10,20,30>", p1, 0.3541861952848022},   // povtrace: …021
      {"wood turbulence <0.1,0.2,0.3> octaves 4 sine_wave rotate x*30", p2, 0.5505515682558172},
      {"gradient y frequency 3 phase 0.2", p2, 0.5499900029802323},
      {"bozo warp { turbulence 0.3 } scale 0.5", p1, 0.5635123408671735},
  };
  for (const Case& c : cases) {
    const std::string declaration = std::string("#declare F = function { pattern { ") + c.pattern + " } }";
    EXPECT_NEAR(value_at(declaration, c.point), c.povray, 2e-16) << c.pattern << " at " << c.point;
  }
}

TEST(PatternFunction, CalledFromAnotherFunctionAndFromFunctionsInc) {
  EXPECT_NEAR(value_at("#declare C = function { pattern { bozo scale <7,1,2> } }\n"
                       "#declare F = function { C(x, y, z) * 2 + 1 }",
                       "<-2.5,0.45,-0.77>"),
              1.6720229961872748, 2e-16);
  EXPECT_NEAR(value_at("#include \"functions.inc\"\n#declare F = function { f_agate(x, y, z) }", "<-2.5,0.45,-0.77>"),
              0.8434522380339728, 2e-16);
}

TEST(PatternFunction, UsesTheSceneNoiseGeneratorWhenItRuns) {
  // The generator is read when the function is called: global_settings after the declaration still count.
  const std::string f = "#declare F = function { pattern { bozo } }\n";
  EXPECT_NEAR(value_at(f + "global_settings { noise_generator 1 }", "<1.37,-0.83,2.11>"), 0.3759022199419663, 2e-16);
  EXPECT_NEAR(value_at(f + "global_settings { noise_generator 3 }", "<1.37,-0.83,2.11>"), 0.4148794839634098, 2e-16);
}

TEST(PatternFunction, WhatTheRendererCannotEvaluateIsRefusedByName) {
  Messages m;
  const ParseError e = parse_error("#declare F = function { pattern { pavement } }\n#declare V = F(1, 2, 3);\n",
                                   with_patterns(m));
  EXPECT_EQ(e.location().line, 2);
  EXPECT_NE(e.bare_message().find("unsupported: the pigment item 'pavement' (at test.pov:1:35) in the pattern "
                                  "function (written at test.pov:1:14)"),
            std::string::npos)
      << e.bare_message();
  const ParseError none = parse_error("#declare F = function { pattern { scale 2 } }\n#declare V = F(1, 2, 3);\n",
                                      with_patterns(m));
  EXPECT_NE(none.bare_message().find("a pattern function without a pattern"), std::string::npos) << none.bare_message();
}

TEST(PatternFunction, ShapesThatEvaluateItWhileRenderingAcceptIt) {
  Messages m;
  const SceneDescription s = parse_scene_text(
      "#version 3.7;\n#declare F = function { pattern { bumps scale 0.2 } }\n"
      "isosurface { function { y - F(x, 0, z) } contained_by { box { -1, 1 } } }\n"
      "height_field { function 8, 8 { F(x, y, z) } }\n"
      "plane { y, 0 pigment { function { F(x, y, z) } } }\n",
      "test.pov", with_patterns(m));
  ASSERT_EQ(s.objects.size(), 3u);
  for (const Object& o : s.objects) EXPECT_FALSE(o.unsupported) << o.unsupported->name;
}

}  // namespace
}  // namespace povtrace::test

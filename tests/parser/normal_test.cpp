// normal { } as the parser records it (POV-Ray's Parse_Tnormal): the kind, the amount after the pattern,
// bump_size, accuracy, no_bump_scale, slope_map, transforms, declared normals, #default and what stays refused.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Normal& normal_of(const SceneDescription& s, std::size_t object = 0, std::size_t layer = 0) {
  const auto& n = s.objects.at(object).texture->layers.at(layer).normal;
  if (!n) throw std::runtime_error("the layer has no normal");
  return *n;
}
SceneDescription scene(const std::string& body) { return parse("#version 3.7;\n" + body); }

// facets (Parse_Pattern FACETS_TOKEN): size 0.1, coords 0, metric 2 by default, reset when chosen again; metric is a
// vector of which x counts; coords and size belong to facets alone.
TEST(NormalParse, FacetsItems) {
  const SceneDescription s = parse("#version 3.7;\nsphere { 0, 1 normal { facets coords 0.5 size 0.3 metric <3, 9, 9> } }\n"
                                   "sphere { 0, 1 normal { facets } }\n");
  const Normal& n = normal_of(s);
  EXPECT_EQ(n.kind, NormalKind::facets);
  EXPECT_EQ(n.facets_coords, 0.5);
  EXPECT_EQ(n.facets_size, 0.3);
  EXPECT_EQ(n.facets_metric, 3.0);
  const Normal& d = normal_of(s, 1);
  EXPECT_EQ(d.facets_coords, 0.0);
  EXPECT_EQ(d.facets_size, 0.1);
  EXPECT_EQ(d.facets_metric, 2.0);
  const ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 normal { bumps size 0.3 } }\n");
  EXPECT_NE(e.bare_message().find("'size' can only be used with facets"), std::string::npos) << e.bare_message();
}

TEST(NormalParse, NormalOnlyPatternWithAmountAndTransform) {
  const SceneDescription s = scene("sphere { 0, 1 normal { bumps 0.3 scale 2 } }\n");
  const Normal& n = normal_of(s);
  EXPECT_EQ(n.kind, NormalKind::bumps);
  EXPECT_EQ(n.amount, 0.3);
  EXPECT_EQ(n.pattern.world_from_pattern, Matrix::scaling({2, 2, 2}));
  EXPECT_EQ(n.accuracy, 0.02);   // POV-Ray's default Delta
  EXPECT_FALSE(n.no_bump_scale);
}

TEST(NormalParse, PatternNormalWithCommaAmountAccuracyAndNoBumpScale) {
  const SceneDescription s = scene("plane { y, 0 normal { gradient x, 0.7 accuracy 0.1 no_bump_scale } }\n");
  const Normal& n = normal_of(s);
  EXPECT_EQ(n.kind, NormalKind::pattern);
  EXPECT_EQ(n.pattern.pattern, PatternKind::gradient);
  EXPECT_EQ(n.amount, 0.7);
  EXPECT_EQ(n.accuracy, 0.1);
  EXPECT_TRUE(n.no_bump_scale);
}

TEST(NormalParse, DefaultAmountIsOneHalfAndBumpSizeReplacesIt) {
  const SceneDescription s = scene("sphere { 0, 1 normal { dents } }\nsphere { 0, 1 normal { dents 2 bump_size 3 } }\n");
  EXPECT_EQ(normal_of(s, 0).amount, 0.5);
  EXPECT_EQ(normal_of(s, 1).amount, 3.0);
}

TEST(NormalParse, DeclaredNormalIsEditedAsACopy) {
  const SceneDescription s = scene(
      "#declare N = normal { ripples 0.4 frequency 3 }\n"
      "sphere { 0, 1 texture { pigment { rgb 1 } normal { N bump_size 0.9 } } }\n"
      "sphere { 0, 1 normal { N } }\n");
  EXPECT_EQ(normal_of(s, 0).kind, NormalKind::ripples);
  EXPECT_EQ(normal_of(s, 0).amount, 0.9);
  EXPECT_EQ(normal_of(s, 0).pattern.frequency, 3.0);
  EXPECT_EQ(normal_of(s, 1).amount, 0.4);
}

TEST(NormalParse, DefaultNormalReachesUntexturedObjectsAndTextureTransformsMoveIt) {
  const SceneDescription s = scene(
      "#default { normal { wrinkles 0.2 } }\n"
      "sphere { 0, 1 }\n"
      "sphere { 0, 1 texture { pigment { rgb 1 } translate x } }\n");
  EXPECT_EQ(normal_of(s, 0).kind, NormalKind::wrinkles);
  EXPECT_EQ(normal_of(s, 1).kind, NormalKind::wrinkles);   // a texture starts from the #default texture
  EXPECT_EQ(normal_of(s, 1).pattern.world_from_pattern, Matrix::translation({1, 0, 0}));
}

TEST(NormalParse, ObjectTransformsMoveTheNormalAndLayersKeepTheirOwn) {
  const SceneDescription s = scene(
      "sphere { 0, 1 texture { pigment { rgb 1 } normal { onion } } texture { pigment { rgbt 1 } } scale 2 }\n");
  ASSERT_EQ(s.objects[0].texture->layers.size(), 2u);
  EXPECT_EQ(normal_of(s, 0, 0).pattern.world_from_pattern, Matrix::scaling({2, 2, 2}));
  EXPECT_FALSE(s.objects[0].texture->layers[1].normal);
}

TEST(NormalParse, SlopeMapEntries) {
  const SceneDescription s = scene("plane { y, 0 normal { gradient x slope_map { [0 <0, 1>] [0.5, <1, 0>] } } }\n");
  const Normal& n = normal_of(s);
  ASSERT_EQ(n.slope_map.size(), 2u);
  EXPECT_EQ(n.slope_map[1].value, 0.5);
  EXPECT_EQ(n.slope_map[1].height, 1.0);
  EXPECT_EQ(n.slope_map[0].slope, 1.0);
}

TEST(NormalParse, ListPatternNormalHasNoFrequency) {
  const SceneDescription s = scene("plane { y, 0 normal { brick 0.8 } }\n");
  const Normal& n = normal_of(s);
  EXPECT_EQ(n.pattern.pattern, PatternKind::brick);
  EXPECT_EQ(n.pattern.frequency, 0.0);
  EXPECT_EQ(n.amount, 0.8);
}

TEST(NormalParse, TypeMayComeLaterThanTheFirstNormalBlock) {
  // POV-Ray checks the type when an object uses the normal (Post_Tnormal), as normmap.pov's #default relies on.
  const SceneDescription s = scene(
      "#default { normal { bump_size 1.5 } }\n#declare N = normal { scale 2 }\n"
      "plane { y, 0 normal { N bumps } }\n");
  EXPECT_EQ(normal_of(s).kind, NormalKind::bumps);
  EXPECT_EQ(normal_of(s).amount, 1.5);
  const ParseError e = parse_error("#version 3.7;\n#default { normal { bump_size 1.5 } }\nsphere { 0, 1 }\n");
  EXPECT_NE(std::string(e.what()).find("no normal type given"), std::string::npos) << e.what();
  // An unrendered pattern keeps its amount after a comma or without one.
  for (const char* text : {"plane { y, 0 normal { pavement , 0.5 } }\n",
                           "plane { y, 0 normal { pavement 10 } }\n"}) {
    const ParseError u = parse_error(std::string("#version 3.7;\n") + text);
    EXPECT_NE(std::string(u.what()).find("unsupported: the normal item 'pavement'"), std::string::npos)
        << u.what();
  }
}

TEST(NormalParse, ErrorsAndRefusals) {
  EXPECT_NE(std::string(parse_error("#version 3.7;\nsphere { 0, 1 normal { scale 2 } }\n").what())
                .find("no normal type given"),
            std::string::npos);
  EXPECT_NE(std::string(parse_error("#version 3.7;\nsphere { 0, 1 normal { bumps color_map { [0 rgb 1] } } }\n")
                            .what())
                .find("can only be used in a pigment"),
            std::string::npos);
  const ParseError average = parse_error("#version 3.7;\nplane { y, 0 normal { average } }\n");
  EXPECT_NE(std::string(average.what()).find("an average normal needs a normal_map"), std::string::npos)
      << average.what();
  const ParseError only = parse_error("#version 3.7;\nplane { y, 0 normal { bumps normal_map { [0 dents] } } }\n");
  EXPECT_NE(std::string(only.what()).find("unsupported: 'normal_map' with a normal-only pattern"), std::string::npos)
      << only.what();
  const ParseError bracket = parse_error("#version 3.7;\nplane { y, 0 normal { bozo normal_map { [0 bumps } } }\n");
  EXPECT_EQ(bracket.location().column, 50);
  EXPECT_NE(std::string(bracket.what()).find("closing the normal_map entry"), std::string::npos) << bracket.what();
}

// normal_map entries, list-pattern normals and an average's weights (Parse_Blend_Map / Parse_Blend_List with
// NORMAL_TYPE): values in single precision; a list's unwritten entries are the #default normal (none here); an
// average's weight defaults to 1; a declared normal may open an entry.
TEST(NormalParse, MapsListsAndAverages) {
  const auto normal_of = [](const std::string& body) {
    const SceneDescription s = parse("#version 3.7;\n#declare R = normal { ripples 0.3 }\nplane { y, 0 normal { " + body + " } }\n");
    return *s.objects.at(0).texture->layers.back().normal;
  };
  const Normal map = normal_of("gradient y normal_map { [0.1 bumps 0.5] [0.7 R scale 2] }");
  ASSERT_EQ(map.map.size(), 2u);
  EXPECT_EQ(map.map[0].value, static_cast<double>(0.1f));
  EXPECT_EQ(map.map[0].normal->kind, NormalKind::bumps);
  EXPECT_EQ(map.map[0].normal->amount, 0.5);
  EXPECT_EQ(map.map[1].normal->kind, NormalKind::ripples);
  EXPECT_EQ(map.map[1].normal->amount, 0.3);
  const Normal list = normal_of("hexagon normal { bumps }, normal { dents }");
  ASSERT_EQ(list.map.size(), 3u);
  EXPECT_EQ(list.map[2].value, 2.0);
  EXPECT_EQ(list.map[2].normal, nullptr);
  EXPECT_TRUE(normal_of("checker").map.empty());   // no entries: the plain pattern normal
  const Normal average = normal_of("average normal_map { [bumps] [3 dents] }");
  EXPECT_EQ(average.kind, NormalKind::average);
  EXPECT_EQ(average.map[0].value, 1.0);
  EXPECT_EQ(average.map[1].value, 3.0);
}

}  // namespace
}  // namespace povtrace::test

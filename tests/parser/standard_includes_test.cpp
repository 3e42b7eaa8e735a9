// Issue 3 item 6: every standard include file of povray-includes parses when included from a scene (after
// colors.inc and shapes.inc, which several depend on), and what it declares can be used where povtrace renders
// it — or is refused by name, at the scene's position, where it does not.
#include <filesystem>

#include "tests/parser/parse_helpers.hpp"

namespace povtrace::test {
namespace {

const char* const kIncludes[] = {"colors", "finish", "metals", "golds", "glass", "textures", "shapes", "shapes2",
                                 "shapesq", "math", "transforms", "consts", "functions", "stdinc", "skies",
                                 "stones", "woods", "rand", "strings", "arrays", "chars"};

class StandardInclude : public ::testing::TestWithParam<const char*> {};

TEST_P(StandardInclude, ParsesWhenIncludedFromAScene) {
  if (!std::filesystem::is_directory(kStandardIncludeDir)) GTEST_SKIP() << "povray-includes is not installed";
  const std::string scene = std::string("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n") +
                            "#include \"colors.inc\"\n#include \"shapes.inc\"\n#include \"" + GetParam() +
                            ".inc\"\nsphere { 0, 1 pigment { rgb 1 } }\n";
  const SceneDescription s = parse(scene);
  EXPECT_EQ(s.objects.size(), 1u);
}

INSTANTIATE_TEST_SUITE_P(Povray37, StandardInclude, ::testing::ValuesIn(kIncludes),
                         [](const auto& p) { return std::string(p.param); });

TEST(StandardIncludeUse, ColoursAndFinishesAreUsable) {
  if (!std::filesystem::is_directory(kStandardIncludeDir)) GTEST_SKIP() << "povray-includes is not installed";
  const SceneDescription s = parse(
      "#version 3.7;\n#include \"colors.inc\"\n#include \"finish.inc\"\n"
      "sphere { 0, 1 pigment { color Orange } finish { Shiny } }\n");
  ASSERT_EQ(s.objects.size(), 1u);
  const TextureLayer& layer = s.objects[0].texture->layers.back();
  EXPECT_DOUBLE_EQ(layer.pigment.colour.r, 1.0);   // colors.inc: Orange = rgb <1, 0.5, 0>
  EXPECT_DOUBLE_EQ(layer.pigment.colour.g, 0.5);
  EXPECT_DOUBLE_EQ(layer.finish.specular, 1.0);    // finish.inc: Shiny = finish { specular 1 roughness 0.001 }
  EXPECT_DOUBLE_EQ(layer.finish.roughness, 0.001);
}

// textures.inc's Tiles_Ptrn(): two repeat warps and a planar one (warp { planar z, 0 }), all rendered now.
TEST(StandardIncludeUse, TilesPatternWithRepeatAndPlanarWarps) {
  if (!std::filesystem::is_directory(kStandardIncludeDir)) GTEST_SKIP() << "povray-includes is not installed";
  const SceneDescription s =
      parse("#version 3.7;\n#include \"colors.inc\"\n#include \"textures.inc\"\n\nsphere { 0, 1 pigment { Tiles_Ptrn() } }\n");
  const Pigment& p = s.objects.at(0).texture->layers.back().pigment;
  EXPECT_FALSE(p.unsupported);
  ASSERT_EQ(p.warps.size(), 3u);
  EXPECT_TRUE(p.warps[0].repeat);
  EXPECT_TRUE(p.warps[1].repeat);
  ASSERT_TRUE(p.warps[2].mapping);
  EXPECT_EQ(p.warps[2].mapping->kind, MappingWarpKind::planar);
}

}  // namespace
}  // namespace povtrace::test

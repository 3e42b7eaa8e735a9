// Radiosity is parsed in full but not computed yet (docs/issue19-study.md §9.3 step 1): the renderer must not
// render such a scene without it, so building it is the error, named and placed at the radiosity block; the
// radiosity importance of objects and the #default alone change nothing and are not refused.
#include <gtest/gtest.h>

#include "parser/parse_scene.hpp"
#include "renderer/render_scene.hpp"

namespace {

using namespace povtrace;

SceneDescription parsed(const std::string& text) {
  ParseOptions o;
  o.message_sink = [](const std::string&) {};
  return parse_scene_text(text, "radiosity.pov", o);
}

TEST(RadiosityRefusal, BuildingASceneWithRadiosityIsTheError) {
  const SceneDescription s = parsed(
      "#version 3.7;\nsphere { 0, 1 pigment { rgb 1 } }\n"
      "global_settings { ambient_light 1 radiosity { count 100 } }\n");
  ASSERT_TRUE(s.radiosity);
  try {
    (void)render::build_render_scene(s, render::BuildOptions{});
    FAIL() << "a radiosity scene must not render without radiosity";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.location().file_name(), "radiosity.pov");
    EXPECT_EQ(e.location().line, 3);
    EXPECT_EQ(e.location().column, 35);
    EXPECT_EQ(e.bare_message(),
              "unsupported: the global setting 'radiosity' is a POV-Ray feature that povtrace does not render yet");
  }
}

TEST(RadiosityRefusal, ImportanceWithoutRadiosityRenders) {
  const SceneDescription s = parsed(
      "#version 3.7;\n#default { radiosity { importance 0.5 } }\n"
      "sphere { 0, 1 pigment { rgb 1 } radiosity { importance 0.25 } }\n");
  EXPECT_FALSE(s.radiosity);
  EXPECT_NO_THROW((void)render::build_render_scene(s, render::BuildOptions{}));
}

}  // namespace

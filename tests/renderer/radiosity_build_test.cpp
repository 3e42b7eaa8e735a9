// Building a radiosity scene: the evaluator exists at +Q9 only (POV-Ray computes radiosity at +Q9 and renders the
// scene as without the block below, docs/issue19-study.md §7); the radiosity importance of objects and the
// #default alone change nothing.
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

TEST(RadiosityBuild, RadiosityIsBuiltAtQ9Only) {
  const SceneDescription s = parsed(
      "#version 3.7;\nsphere { 0, 1 pigment { rgb 1 } }\n"
      "global_settings { ambient_light 1 radiosity { count 100 } }\n");
  ASSERT_TRUE(s.radiosity);
  render::BuildOptions q9;
  EXPECT_TRUE(render::build_render_scene(s, q9).radiosity);
  render::BuildOptions q8;
  q8.quality = 8;
  EXPECT_FALSE(render::build_render_scene(s, q8).radiosity);
}

TEST(RadiosityBuild, ImportanceWithoutRadiosityRenders) {
  const SceneDescription s = parsed(
      "#version 3.7;\n#default { radiosity { importance 0.5 } }\n"
      "sphere { 0, 1 pigment { rgb 1 } radiosity { importance 0.25 } }\n");
  EXPECT_FALSE(s.radiosity);
  EXPECT_NO_THROW((void)render::build_render_scene(s, render::BuildOptions{}));
}

}  // namespace

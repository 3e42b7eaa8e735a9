// Pixels beyond single precision's range (render.cpp to_pixel): a pigment of rgb 3e38 is legal SDL; lit, its
// pixels saturate at the largest float instead of becoming infinite. A colour beyond float's range itself (rgb
// 1e59, found by the render fuzzer) is stored saturated (parser/expressions/values.hpp), so no pixel is NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

#include "parser/parse_scene.hpp"
#include "renderer/render.hpp"

namespace {

using namespace povtrace;

image::Image rendered(const std::string& colour) {
  ParseOptions o;
  o.message_sink = [](const std::string&) {};
  const SceneDescription scene = parse_scene_text(
      "camera { location -3 * z look_at 0 }\nlight_source { -5 * z, 1 }\n"
      "sphere { 0, 1 pigment { rgb " + colour + " } finish { ambient 0 diffuse 1 } }\n",
      "huge.pov", o);
  const render::RenderScene built = render::build_render_scene(scene, {});
  render::RenderSettings s;
  s.width = 8;
  s.height = 6;
  s.threads = 1;
  return render::render(built, s).image;
}

void expect_finite_and_saturated(const image::Image& img) {
  const float top = std::numeric_limits<float>::max();
  bool saturated = false;
  for (std::size_t i = 0; i < img.rgba.size(); ++i) {
    const float v = img.rgba[i];
    ASSERT_TRUE(std::isfinite(v)) << "value " << v << " at index " << i;
    saturated = saturated || v == top;
  }
  EXPECT_TRUE(saturated);   // the sphere's green reached the top of the range
}

TEST(PixelRange, ColoursBeyondFloatSaturateInsteadOfBecomingInfinite) {
  expect_finite_and_saturated(rendered("<0.5, 3e38, -3e38>"));
  expect_finite_and_saturated(rendered("<0.5, 1e59, -1e59>"));
}

}  // namespace

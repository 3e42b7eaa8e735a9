// Focal blur items of camera { } as POV-Ray 3.7's Parse_Camera and Parse_Camera_Mods read them: values, defaults,
// blur_samples MIN, MAX, the illegal values POV-Ray refuses or replaces by the default with a warning, and the focal
// distance (focal_point's distance from the location before the camera's transforms, else the direction's length
// as angle or look_at made it, else 1).
#include <gtest/gtest.h>

#include <cmath>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

FocalBlur blur_of(const std::string& camera_body, Messages* messages = nullptr) {
  return parse("#version 3.7;\ncamera { " + camera_body + " }\n", messages).camera.focal_blur;
}
std::string error_of(const std::string& camera_body) {
  return parse_error("#version 3.7;\ncamera { " + camera_body + " }\n").bare_message();
}

TEST(FocalBlurParse, DefaultsArePovRays) {
  const FocalBlur b = blur_of("location -5*z");
  EXPECT_EQ(b.aperture, 0.0);
  EXPECT_EQ(b.samples, 0);
  EXPECT_EQ(b.min_samples, 0);
  EXPECT_EQ(b.confidence, 0.9);
  EXPECT_EQ(b.variance, 1.0 / 10000.0);
  EXPECT_EQ(b.focal_distance, 1.0);   // no angle, no look_at: POV-Ray's Direction_Length stays 1
}

TEST(FocalBlurParse, ItemsAndSampleCounts) {
  const FocalBlur b = blur_of("aperture 0.4 blur_samples 20.7 confidence 0.95 variance 1/255");
  EXPECT_EQ(b.aperture, 0.4);
  EXPECT_EQ(b.samples, 20);   // truncated, as POV-Ray's int
  EXPECT_EQ(b.min_samples, 0);
  EXPECT_EQ(b.confidence, 0.95);
  EXPECT_EQ(b.variance, 1.0 / 255.0);
  const FocalBlur m = blur_of("aperture 1 blur_samples 5, 37");
  EXPECT_EQ(m.min_samples, 5);
  EXPECT_EQ(m.samples, 37);
  const FocalBlur same = blur_of("aperture 1 blur_samples 9, 9");
  EXPECT_EQ(same.min_samples, 9);
  EXPECT_EQ(same.samples, 9);
}

TEST(FocalBlurParse, IllegalValues) {
  EXPECT_NE(error_of("blur_samples 0").find("blur_samples must be at least 1"), std::string::npos);
  EXPECT_NE(error_of("blur_samples -3").find("blur_samples must be at least 1"), std::string::npos);
  EXPECT_NE(error_of("blur_samples 0.5").find("blur_samples must be at least 1"), std::string::npos);
  EXPECT_NE(error_of("blur_samples 10, 4").find("must not be larger than its maximum"), std::string::npos);
  // Confidence outside (0, 1) and variance outside [0, 1]: POV-Ray warns and keeps its default.
  Messages messages;
  const FocalBlur b = blur_of("confidence 1 variance 2", &messages);
  EXPECT_EQ(b.confidence, 0.9);
  EXPECT_EQ(b.variance, 1.0 / 10000.0);
  EXPECT_NE(messages.joined().find("illegal confidence value"), std::string::npos);
  EXPECT_NE(messages.joined().find("illegal variance value"), std::string::npos);
  EXPECT_EQ(blur_of("variance 0").variance, 0.0);
}

TEST(FocalBlurParse, FocalDistance) {
  // focal_point: its distance from the final location, whatever the order, before the transforms.
  EXPECT_EQ(blur_of("focal_point <3, 4, 0> location 0").focal_distance, 5.0);
  EXPECT_EQ(blur_of("location <0, 0, -2> focal_point <0, 0, 1> scale 10").focal_distance, 3.0);
  // look_at: the direction's length before look_at turns it (1 by default, 2 here).
  EXPECT_EQ(blur_of("location -5*z direction 2*z look_at 0").focal_distance, 2.0);
  // angle: the length it gives the direction, |right| / tan(angle/2) / 2.
  const double expected = 1.33 / std::tan(60.0 * M_PI / 360.0) / 2.0;
  EXPECT_NEAR(blur_of("angle 60").focal_distance, expected, 1e-15);
  // A direction alone does not count (POV-Ray's Direction_Length stays 1); a focal point at the location gives 1.
  EXPECT_EQ(blur_of("direction 3*z").focal_distance, 1.0);
  EXPECT_EQ(blur_of("location <1, 2, 3> focal_point <1, 2, 3>").focal_distance, 1.0);
}

TEST(FocalBlurParse, DeclaredCameraKeepsItsBlur) {
  const SceneDescription s = parse("#version 3.7;\n#declare C = camera { location -4*z aperture 0.5 blur_samples 7 "
                                   "focal_point 0 }\ncamera { C translate x }\n");
  EXPECT_EQ(s.camera.focal_blur.aperture, 0.5);
  EXPECT_EQ(s.camera.focal_blur.samples, 7);
  EXPECT_EQ(s.camera.focal_blur.focal_distance, 4.0);
}

TEST(FocalBlurParse, OldSyntax) {
  // Before 3.5: one number for blur_samples, and focal_point measured from the location written before it.
  const SceneDescription s =
      parse("#version 3.1;\ncamera { location -4*z focal_point 0 location -8*z blur_samples 12 aperture 1 }\n");
  EXPECT_EQ(s.camera.focal_blur.samples, 12);
  EXPECT_EQ(s.camera.focal_blur.focal_distance, 4.0);
}

TEST(FocalBlurParse, MeshCameraBlurIsReportedByName) {
  const std::string text = "#version 3.7;\ncamera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } "
                           "aperture 0.5 blur_samples 4 }\nsphere { 0, 1 pigment { rgb 1 } }\n";
  const ParseError e = parse_error(text);
  EXPECT_NE(e.bare_message().find("unsupported: focal blur (aperture, blur_samples) on a mesh_camera"),
            std::string::npos);
  EXPECT_EQ(e.location().line, 2);
}

TEST(FocalBlurParse, BokehIsReportedByName) {
  EXPECT_NE(parse_error("#version 3.7;\ncamera { bokeh { pigment { rgb 1 } } }\n").bare_message().find(
                "unsupported: the camera item 'bokeh'"),
            std::string::npos);
}

}  // namespace
}  // namespace povtrace::test

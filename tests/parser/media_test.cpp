// media { } and density { } as POV-Ray 3.7's Parse_Media reads them (parser/textures/media.cpp): defaults per
// #version, every setting, densities and their maps, declared values, transforms, and the errors POV-Ray gives.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Media& interior_media(const SceneDescription& s, std::size_t i = 0) {
  return s.objects.at(0).interior->media->at(i);
}

TEST(MediaParse, DefaultsFollowTheLanguageVersion) {
  const Media m37 = interior_media(parse("#version 3.7;\nsphere { 0, 1 hollow interior { media { } } }\n"));
  EXPECT_EQ(m37.method, 3);
  EXPECT_EQ(m37.intervals, 1);
  EXPECT_EQ(m37.min_samples, 10);
  EXPECT_EQ(m37.max_samples, 10);
  const Media m31 = interior_media(parse("#version 3.1;\nsphere { 0, 1 hollow interior { media { } } }\n"));
  EXPECT_EQ(m31.method, 1);
  EXPECT_EQ(m31.intervals, 10);
  EXPECT_EQ(m31.min_samples, 1);
  EXPECT_EQ(m31.max_samples, 1);
}

TEST(MediaParse, EverySetting) {
  const Media m = interior_media(parse(
      "#version 3.7;\nsphere { 0, 1 hollow interior { media {\n"
      "  method 2 intervals 4 samples 3, 9 confidence 0.8 variance 0.01 ratio 0.7 jitter 0.5\n"
      "  aa_threshold 0.2 aa_level 4 absorption <0.1, 0.2, 0.3> emission 0.4 collect off\n"
      "  scattering { 5, rgb <1, 2, 3> eccentricity 0.25 extinction 0.5 } } } }\n"));
  EXPECT_EQ(m.method, 2);
  EXPECT_EQ(m.intervals, 4);
  EXPECT_EQ(m.min_samples, 3);
  EXPECT_EQ(m.max_samples, 9);
  EXPECT_DOUBLE_EQ(m.confidence, 0.8);
  EXPECT_DOUBLE_EQ(m.variance, 0.01);
  EXPECT_DOUBLE_EQ(m.ratio, 0.7);
  EXPECT_DOUBLE_EQ(m.jitter, 0.5);
  EXPECT_DOUBLE_EQ(m.aa_threshold, 0.2);
  EXPECT_EQ(m.aa_level, 4);
  EXPECT_FLOAT_EQ(static_cast<float>(m.absorption.b), 0.3f);
  EXPECT_FLOAT_EQ(static_cast<float>(m.emission.g), 0.4f);
  EXPECT_FALSE(m.collect);
  EXPECT_EQ(m.scattering_type, 5);
  EXPECT_DOUBLE_EQ(m.scattering.b, 3.0);
  EXPECT_DOUBLE_EQ(m.eccentricity, 0.25);
  EXPECT_DOUBLE_EQ(m.extinction, 0.5);
}

TEST(MediaParse, SeveralMediaAndDensitiesKeepTheirOrder) {
  const SceneDescription s = parse(
      "#version 3.7;\nsphere { 0, 1 hollow interior {\n"
      "  media { emission 1 density { spherical density_map { [0 rgb 0] [1 rgb 1] } } density { rgb 0.5 } }\n"
      "  media { absorption 1 } } }\n");
  ASSERT_EQ(s.objects[0].interior->media->size(), 2u);
  const Media& first = interior_media(s, 0);
  ASSERT_EQ(first.densities.size(), 2u);
  EXPECT_EQ(first.densities[0].pattern, PatternKind::spherical);
  ASSERT_EQ(first.densities[0].entries.size(), 2u);
  ASSERT_TRUE(first.densities[0].entries[1].pigment);   // density_map entries are densities
  EXPECT_DOUBLE_EQ(first.densities[0].entries[1].pigment->colour.r, 1.0);
  EXPECT_EQ(first.densities[1].pattern, PatternKind::solid);
  EXPECT_TRUE(interior_media(s, 1).densities.empty());
}

// A transform inside media moves the densities written before it only (Transform_Density on the list so far);
// an object's transform moves its interior's media.
TEST(MediaParse, TransformsMoveTheDensitiesWrittenSoFar) {
  const SceneDescription s = parse(
      "#version 3.7;\nsphere { 0, 1 hollow interior { media {\n"
      "  density { bozo } translate x density { agate } } } translate y }\n");
  const Media& m = interior_media(s);
  EXPECT_EQ(m.densities[0].world_from_pattern.point({0, 0, 0}), (Vec3{1, 1, 0}));
  EXPECT_EQ(m.densities[1].world_from_pattern.point({0, 0, 0}), (Vec3{0, 1, 0}));
}

TEST(MediaParse, DeclaredMediaDensityAndMaps) {
  const SceneDescription s = parse(
      "#version 3.7;\n#declare D = density { granite }\n#declare DM = density_map { [0 rgb 1] [1 rgb 0] }\n"
      "#declare M = media { scattering { 2, 0.1 } density { D density_map { DM } } }\n"
      "sphere { 0, 1 hollow interior { media { M emission 0.5 } } }\nmedia { M }\n");
  const Media& m = interior_media(s);
  EXPECT_EQ(m.scattering_type, 2);
  EXPECT_FLOAT_EQ(static_cast<float>(m.emission.r), 0.5f);
  EXPECT_EQ(m.densities.at(0).pattern, PatternKind::granite);
  EXPECT_EQ(m.densities.at(0).entries.size(), 2u);
  ASSERT_EQ(s.atmosphere.size(), 1u);
  EXPECT_EQ(s.atmosphere[0].scattering_type, 2);
}

TEST(MediaParse, LightsMediaInteractionAndAttenuation) {
  const SceneDescription s = parse(
      "#version 3.7;\nlight_source { 0, 1 }\nlight_source { 0, 1 media_interaction off media_attenuation on }\n");
  EXPECT_TRUE(s.lights.at(0).media_interaction);
  EXPECT_FALSE(s.lights.at(0).media_attenuation);
  EXPECT_FALSE(s.lights.at(1).media_interaction);
  EXPECT_TRUE(s.lights.at(1).media_attenuation);
}

// A density povtrace cannot evaluate is never left out silently: the object or the media is refused by name.
TEST(MediaParse, UnrenderedDensityItemsAreNamed) {
  const ParseError in_object =
      parse_error("#version 3.7;\nsphere { 0, 1 hollow interior { media { emission 1 density { facets } } } }\n");
  EXPECT_NE(in_object.bare_message().find("the density item 'facets'"), std::string::npos) << in_object.what();
  const ParseError atmosphere = parse_error("#version 3.7;\nmedia { emission 1 density { facets } }\n");
  EXPECT_NE(atmosphere.bare_message().find("the density item 'facets'"), std::string::npos) << atmosphere.what();
}

// Fake caustics: interior { caustics C } stores 45·C (Parse_Interior); the pre-3.1 finish item moves into the
// interior unscaled when the object is placed (Post_Process), with a warning.
TEST(InteriorParse, CausticsScaledInTheInteriorAndUnscaledFromTheFinish) {
  const SceneDescription s = parse("#version 3.7;\nsphere { 0, 1 interior { caustics 2 } }\n");
  EXPECT_DOUBLE_EQ(s.objects.at(0).interior->caustics, 90.0);
  Messages messages;
  const SceneDescription legacy =
      parse("#version 3.7;\nsphere { 0, 1 pigment { rgbf 1 } finish { caustics 20 } }\n", &messages);
  EXPECT_DOUBLE_EQ(legacy.objects.at(0).interior->caustics, 20.0);
  EXPECT_NE(messages.joined().find("interior { caustics"), std::string::npos) << messages.joined();
}

struct MediaError {
  std::string name, text, fragment;
};
class MediaErrors : public ::testing::TestWithParam<MediaError> {};
TEST_P(MediaErrors, NamedWithTheirPosition) {
  const ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 hollow interior { media { " + GetParam().text +
                                   " } } }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_NE(e.bare_message().find(GetParam().fragment), std::string::npos) << e.bare_message();
}
INSTANTIATE_TEST_SUITE_P(
    POVRayRules, MediaErrors,
    ::testing::Values(MediaError{"Method", "method 4", "method choices are 1, 2 or 3"},
                      MediaError{"Intervals", "intervals 0", "at least one interval"},
                      MediaError{"Samples", "samples 0", "at least one sample"},
                      MediaError{"SamplesOrder", "samples 5, 2", "smaller than the minimum"},
                      MediaError{"Confidence", "confidence 1", "confidence must be"},
                      MediaError{"AaThreshold", "aa_threshold 0", "greater than zero"},
                      MediaError{"AaLevel", "aa_level 0", "at least one"},
                      MediaError{"Eccentricity", "scattering { 1, 1 eccentricity 0.5 }", "type 5"},
                      MediaError{"PigmentMap", "density { bozo pigment_map { [0 rgb 1] } }", "density_map"},
                      MediaError{"Unknown", "colour 1", "in media { }"}),
    [](const ::testing::TestParamInfo<MediaError>& i) { return i.param.name; });

}  // namespace
}  // namespace povtrace::test

// photons { } as POV-Ray 3.7's parser reads it (docs/issue20-photons.md §1): global settings with their defaults and
// checks, object flags with POV-Ray's pass_through rule and their inheritance by CSG children, light flags, photon
// map files, and the features still refused by name.
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

TEST(PhotonSettingsParse, DefaultsOfABlock) {
  const SceneDescription s = parse("#version 3.7;\nglobal_settings { photons { } }\n");
  ASSERT_TRUE(s.photons.has_value());
  const PhotonSettings& p = *s.photons;
  EXPECT_DOUBLE_EQ(p.spacing, 1.0);
  EXPECT_EQ(p.count, 0);
  EXPECT_EQ(p.gather_min, 20);
  EXPECT_EQ(p.gather_max, 100);
  EXPECT_DOUBLE_EQ(p.expand_tolerance, 0.2);
  EXPECT_EQ(p.expand_min, 35);
  EXPECT_DOUBLE_EQ(p.jitter, 0.4);
  EXPECT_DOUBLE_EQ(p.autostop, 0.5);
  EXPECT_FALSE(p.max_trace_level.has_value());
  EXPECT_FALSE(p.adc_bailout.has_value());
  EXPECT_LT(p.radius, 0.0);
  EXPECT_DOUBLE_EQ(p.radius_multiplier, 1.0);
  EXPECT_TRUE(p.load_file.empty());
  EXPECT_TRUE(p.save_file.empty());
  EXPECT_FALSE(parse("#version 3.7;\nglobal_settings { }\n").photons.has_value());
}

TEST(PhotonSettingsParse, EverySetting) {
  const SceneDescription s = parse(
      "#version 3.7;\nglobal_settings { photons { spacing 0.02 count 5000 gather 10, 50 expand_thresholds 0.3, 12\n"
      "  jitter 0.7 autostop 0.25 max_trace_level 9 adc_bailout 0.02 radius 0.5, 2, 0.25, 3 save_file \"m.ph\" } }\n");
  const PhotonSettings& p = *s.photons;
  EXPECT_DOUBLE_EQ(p.spacing, 0.02);
  EXPECT_EQ(p.count, 5000);
  EXPECT_EQ(p.gather_min, 10);
  EXPECT_EQ(p.gather_max, 50);
  EXPECT_DOUBLE_EQ(p.expand_tolerance, 0.3);
  EXPECT_EQ(p.expand_min, 12);
  EXPECT_DOUBLE_EQ(p.jitter, 0.7);
  EXPECT_DOUBLE_EQ(p.autostop, 0.25);
  EXPECT_EQ(p.max_trace_level, 9);
  EXPECT_DOUBLE_EQ(*p.adc_bailout, 0.02);
  EXPECT_DOUBLE_EQ(p.radius, 0.5);
  EXPECT_DOUBLE_EQ(p.radius_multiplier, 2);
  EXPECT_DOUBLE_EQ(p.media_radius, 0.25);
  EXPECT_DOUBLE_EQ(p.media_radius_multiplier, 3);
  EXPECT_EQ(p.save_file, "m.ph");
  EXPECT_EQ(p.file_loc.line, 3);
}

// Each photons block starts from the defaults again (POV-Ray resets them at the keyword).
TEST(PhotonSettingsParse, ALaterBlockStartsFromTheDefaults) {
  const SceneDescription s = parse(
      "#version 3.7;\nglobal_settings { photons { spacing 0.02 jitter 0 } }\nglobal_settings { photons { count 9 } }\n");
  EXPECT_DOUBLE_EQ(s.photons->spacing, 1.0);
  EXPECT_DOUBLE_EQ(s.photons->jitter, 0.4);
  EXPECT_EQ(s.photons->count, 9);
}

TEST(PhotonSettingsParse, MaxTraceLevelClampedAsTheScenes) {
  EXPECT_EQ(parse("global_settings { photons { max_trace_level 100000 } }").photons->max_trace_level, 256);
  EXPECT_EQ(parse("global_settings { photons { max_trace_level -3 } }").photons->max_trace_level, 1);
}

TEST(PhotonSettingsParse, GatherMaximumZeroLeavesPhotonsOff) {
  Messages m;
  const SceneDescription s = parse("#version 3.7;\nglobal_settings { photons { gather 0, 0 } }\n", &m);
  EXPECT_FALSE(s.photons.has_value());
  EXPECT_NE(m.joined().find("photons disabled"), std::string::npos) << m.joined();
}

TEST(PhotonSettingsParse, OneFileNameTheLastWins) {
  Messages m;
  const SceneDescription s =
      parse("#version 3.7;\nglobal_settings { photons { save_file \"a.ph\" load_file \"b.ph\" } }\n", &m);
  EXPECT_EQ(s.photons->load_file, "b.ph");
  EXPECT_TRUE(s.photons->save_file.empty());
  EXPECT_NE(m.joined().find("switching to load mode"), std::string::npos) << m.joined();
}

TEST(PhotonSettingsParse, NegativeExpandThresholdsBecomeZeroWithAWarning) {
  Messages m;
  const SceneDescription s = parse("#version 3.7;\nglobal_settings { photons { expand_thresholds -1, -2 } }\n", &m);
  EXPECT_DOUBLE_EQ(s.photons->expand_tolerance, 0.0);
  EXPECT_EQ(s.photons->expand_min, 0);
  EXPECT_NE(m.joined().find("expand_thresholds"), std::string::npos);
}

struct PhotonError {
  std::string name, settings, fragment;
  int column;
};
class PhotonSettingErrors : public ::testing::TestWithParam<PhotonError> {};
TEST_P(PhotonSettingErrors, NamedWithTheirPosition) {
  const ParseError e = parse_error("#version 3.7;\nglobal_settings { photons { " + GetParam().settings + " } }\n");
  EXPECT_EQ(e.location().line, 2);
  EXPECT_EQ(e.location().column, GetParam().column) << e.what();
  EXPECT_NE(std::string(e.what()).find(GetParam().fragment), std::string::npos) << e.what();
}
INSTANTIATE_TEST_SUITE_P(
    Photons, PhotonSettingErrors,
    ::testing::Values(PhotonError{"min_above_max", "gather 50, 20", "min_gather_count must be less", 19},
                      PhotonError{"negative_min", "gather -1, 20", "cannot be negative", 19},
                      PhotonError{"zero_spacing", "spacing 0", "spacing must be positive", 37},
                      PhotonError{"media_photons", "media 10, 2", "media photons", 29},
                      PhotonError{"negative_media_steps", "media -1", "max media steps", 35},
                      PhotonError{"unknown_item", "radiosity 2", "a photons setting", 29}),
    [](const ::testing::TestParamInfo<PhotonError>& i) { return i.param.name; });

TEST(ObjectPhotonsParse, FlagsAsWritten) {
  const SceneDescription s = parse(
      "#version 3.7;\nsphere { 0, 1 photons { target 0.5 refraction on reflection off collect off } }\n"
      "sphere { 0, 1 photons { pass_through } }\nsphere { 0, 1 }\n");
  const ObjectPhotons& a = s.objects.at(0).photons;
  EXPECT_DOUBLE_EQ(a.target, 0.5);
  EXPECT_EQ(a.refraction, true);
  EXPECT_EQ(a.reflection, false);
  EXPECT_FALSE(a.collect);
  EXPECT_TRUE(s.objects.at(1).photons.pass_through);
  EXPECT_EQ(s.objects.at(2).photons, ObjectPhotons{});
  EXPECT_DOUBLE_EQ(parse("sphere { 0, 1 photons { target } }").objects.at(0).photons.target, 1.0);
  EXPECT_DOUBLE_EQ(parse("sphere { 0, 1 photons { target -2 } }").objects.at(0).photons.target, 0.0);
}

// POV-Ray's CheckPassThru: a pass_through target cannot refract; whichever came last gives way, with a warning.
TEST(ObjectPhotonsParse, PassThroughTargetsCannotRefract) {
  Messages m;
  const SceneDescription s = parse(
      "sphere { 0, 1 photons { target pass_through } }\n"
      "sphere { 0, 1 photons { target refraction on pass_through } }\n"
      "sphere { 0, 1 photons { pass_through target refraction on } }\n",
      &m);
  EXPECT_EQ(s.objects.at(0).photons.refraction, false);
  EXPECT_TRUE(s.objects.at(0).photons.pass_through);
  EXPECT_EQ(s.objects.at(1).photons.refraction, false);   // pass_through came last
  EXPECT_TRUE(s.objects.at(1).photons.pass_through);
  EXPECT_EQ(s.objects.at(2).photons.refraction, true);    // refraction on came last
  EXPECT_FALSE(s.objects.at(2).photons.pass_through);
  EXPECT_NE(m.joined().find("Cannot use pass_through with refraction & target"), std::string::npos);
}

TEST(ObjectPhotonsParse, CsgChildrenTakeTheParentsFlags) {
  const SceneDescription s = parse(
      "merge { sphere { 0, 1 photons { reflection on } } sphere { 1, 1 photons { refraction off target 2 } }\n"
      "  photons { target refraction on collect off } }\n");
  const auto& children = std::get<Csg>(s.objects.at(0).shape).children;
  EXPECT_DOUBLE_EQ(children.at(0).photons.target, 1.0);
  EXPECT_EQ(children.at(0).photons.refraction, true);
  EXPECT_EQ(children.at(0).photons.reflection, true);   // the parent did not write reflection: the child's stays
  EXPECT_FALSE(children.at(0).photons.collect);
  EXPECT_DOUBLE_EQ(children.at(1).photons.target, 1.0);   // the parent's multiplier replaces the child's
  EXPECT_EQ(children.at(1).photons.refraction, true);
}

TEST(LightPhotonsParse, FlagsAsWritten) {
  const SceneDescription s = parse(
      "light_source { 0, 1 photons { refraction on reflection off area_light } }\nlight_source { 0, 1 }\n");
  EXPECT_EQ(s.lights.at(0).photon_refraction, true);
  EXPECT_EQ(s.lights.at(0).photon_reflection, false);
  EXPECT_TRUE(s.lights.at(0).photon_area_light);
  EXPECT_FALSE(s.lights.at(1).photon_refraction.has_value());
  EXPECT_FALSE(s.lights.at(1).photon_area_light);
  const ParseError e = parse_error("light_source { 0, 1 photons { target } }\n");
  EXPECT_NE(std::string(e.what()).find("refraction, reflection, area_light"), std::string::npos) << e.what();
}

TEST(ObjectPhotonsParse, UnknownItemIsAnError) {
  const ParseError e = parse_error("sphere { 0, 1 photons { spacing 2 } }\n");
  EXPECT_EQ(e.location().column, 25);
  EXPECT_NE(std::string(e.what()).find("target, refraction, reflection, collect, pass_through"), std::string::npos);
}

TEST(ProjectedThrough, TheObjectMovesWithTheLightAndLosesTextureAndInterior) {
  Messages m;
  const SceneDescription sd = parse(
      "#version 3.7;\n"
      "#declare Slab = box { <-1, 0, -1>, <1, 0.2, 1> pigment { rgb 1 } interior { ior 1.5 } }\n"
      "light_source { <0, 5, 0> rgb 1 projected_through { Slab scale 2 } translate x }\n",
      &m);
  ASSERT_EQ(sd.lights.size(), 1u);
  ASSERT_EQ(sd.lights[0].projected_through.size(), 1u);
  EXPECT_TRUE(sd.objects.empty());   // photons use it; it is not placed in the scene
  const Object& slab = sd.lights[0].projected_through[0];
  EXPECT_FALSE(slab.texture);
  EXPECT_FALSE(slab.interior);
  EXPECT_NE(m.joined().find("cannot have an interior"), std::string::npos) << m.joined();
  EXPECT_NE(m.joined().find("cannot have a texture"), std::string::npos) << m.joined();
  // Not moved to the light's location; the light's later translate moves it.
  const auto& box = std::get<Box>(slab.shape);
  const Vec3 c2 = slab.world_from_object.point(box.corner2);
  EXPECT_EQ(c2, (Vec3{3, 0.4, 2}));
}

TEST(ProjectedThrough, OneObjectPerLight) {
  const ParseError e = parse_error(
      "#version 3.7;\nlight_source { 0, 1 projected_through { sphere { 0, 1 } }\n"
      "  projected_through { sphere { 0, 2 } } }\n");
  EXPECT_EQ(e.location().line, 3);
  EXPECT_EQ(e.location().column, 3);
  EXPECT_NE(e.bare_message().find("at most one projected_through"), std::string::npos) << e.bare_message();
  const ParseError notobject = parse_error("#version 3.7;\nlight_source { 0, 1 projected_through { 1 } }\n");
  EXPECT_NE(notobject.bare_message().find("an object in projected_through"), std::string::npos);
}

}  // namespace
}  // namespace povtrace::test

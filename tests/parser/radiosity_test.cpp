// Radiosity's SDL as POV-Ray 3.7 parses it (docs/issue19-study.md §1, §9.3 step 1): every setting's default, each
// range error with its position and POV-Ray's message, the count/nearest_count pairs, the post-parse
// minimum_reuse/maximum_reuse fix-up and pretrace check, the warnings, and radiosity importance as objects, CSG
// children, looks_like objects and #default give it.
#include <string>

#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

// A #version 3.7 scene whose global_settings hold `radiosity { <items> }` (line 2).
std::string with_block(const std::string& items) {
  return "#version 3.7;\nglobal_settings { radiosity { " + items + " } }\n";
}

RadiositySettings settings_of(const std::string& items, Messages* messages = nullptr) {
  const SceneDescription s = parse(with_block(items), messages);
  if (!s.radiosity) {
    ADD_FAILURE() << "no radiosity settings for: " << items;
    return {};
  }
  return *s.radiosity;
}

TEST(RadiositySettings, NoBlockMeansNoRadiosity) {
  const SceneDescription s = parse("#version 3.7;\nglobal_settings { assumed_gamma 1 }\n");
  EXPECT_FALSE(s.radiosity);
  EXPECT_DOUBLE_EQ(s.radiosity_default_importance, 1.0);
}

// pov: radiosity.h SceneRadiositySettings' constructor.
TEST(RadiositySettings, EmptyBlockHasPovRaysDefaults) {
  const SceneDescription scene = parse(with_block(""));
  ASSERT_TRUE(scene.radiosity);
  const RadiositySettings& s = *scene.radiosity;
  EXPECT_EQ(s.loc.line, 2);
  EXPECT_EQ(s.loc.column, 19);
  EXPECT_DOUBLE_EQ(s.adc_bailout, 0.01);
  EXPECT_FALSE(s.always_sample);
  EXPECT_DOUBLE_EQ(s.brightness, 1.0);
  EXPECT_EQ(s.count, 35);
  EXPECT_EQ(s.direction_pool, 1600);
  EXPECT_DOUBLE_EQ(s.error_bound, 1.8);
  EXPECT_DOUBLE_EQ(s.gray_threshold, 0.0);
  EXPECT_DOUBLE_EQ(s.low_error_factor, 0.5);
  EXPECT_DOUBLE_EQ(s.max_sample, -1.0);
  EXPECT_DOUBLE_EQ(s.maximum_reuse, 0.2);
  EXPECT_DOUBLE_EQ(s.minimum_reuse, 0.015);
  EXPECT_EQ(s.nearest_count, 5);
  EXPECT_EQ(s.nearest_count_adaptive, 0);
  EXPECT_EQ(s.recursion_limit, 2);
  EXPECT_FALSE(s.normal);
  EXPECT_FALSE(s.media);
  EXPECT_FALSE(s.subsurface);
  EXPECT_DOUBLE_EQ(s.pretrace_start, 0.08);
  EXPECT_DOUBLE_EQ(s.pretrace_end, 0.04);
}

TEST(RadiositySettings, EveryItemIsRead) {
  const RadiositySettings s = settings_of(
      "adc_bailout 0.005 always_sample on brightness 1.5 count 200, 3000 error_bound 0.5 gray_threshold 0.25 "
      "low_error_factor 0.3 max_sample 2.5 maximum_reuse 0.1 minimum_reuse 0.02 nearest_count 10, 4 "
      "recursion_limit 3 normal on media 1 subsurface yes pretrace_start 0.16 pretrace_end 0.01");
  EXPECT_DOUBLE_EQ(s.adc_bailout, 0.005);
  EXPECT_TRUE(s.always_sample);
  EXPECT_DOUBLE_EQ(s.brightness, 1.5);
  EXPECT_EQ(s.count, 200);
  EXPECT_EQ(s.direction_pool, 3000);
  EXPECT_DOUBLE_EQ(s.error_bound, 0.5);
  EXPECT_DOUBLE_EQ(s.gray_threshold, 0.25);
  EXPECT_DOUBLE_EQ(s.low_error_factor, 0.3);
  EXPECT_DOUBLE_EQ(s.max_sample, 2.5);
  EXPECT_DOUBLE_EQ(s.maximum_reuse, 0.1);
  EXPECT_DOUBLE_EQ(s.minimum_reuse, 0.02);
  EXPECT_EQ(s.nearest_count, 10);
  EXPECT_EQ(s.nearest_count_adaptive, 4);
  EXPECT_EQ(s.recursion_limit, 3);
  EXPECT_TRUE(s.normal);
  EXPECT_TRUE(s.media);
  EXPECT_TRUE(s.subsurface);
  EXPECT_DOUBLE_EQ(s.pretrace_start, 0.16);
  EXPECT_DOUBLE_EQ(s.pretrace_end, 0.01);
}

// The pool is max(1600, count) whenever count is written without it, and the edges of each range are accepted.
TEST(RadiositySettings, CountSetsTheDirectionPool) {
  EXPECT_EQ(settings_of("count 50").direction_pool, 1600);
  EXPECT_EQ(settings_of("count 100000").direction_pool, 100000);
  EXPECT_EQ(settings_of("count 1599, 1599").direction_pool, 1599);   // the only way to POV-Ray's table
  EXPECT_EQ(settings_of("count 10 20").direction_pool, 20);          // the comma is optional, as in POV-Ray
  EXPECT_EQ(settings_of("count 50, 3000 count 40").direction_pool, 1600);
  EXPECT_EQ(settings_of("count 7.9").count, 7);                      // truncated, as POV-Ray's (int) cast
  EXPECT_EQ(settings_of("nearest_count 20, 19").nearest_count_adaptive, 19);
  EXPECT_EQ(settings_of("nearest_count 7").nearest_count_adaptive, 0);
  EXPECT_EQ(settings_of("recursion_limit 20").recursion_limit, 20);
  EXPECT_DOUBLE_EQ(settings_of("gray_threshold 1").gray_threshold, 1.0);
  EXPECT_DOUBLE_EQ(settings_of("minimum_reuse 0").minimum_reuse, 0.0);
  EXPECT_DOUBLE_EQ(settings_of("pretrace_start 1 pretrace_end 1").pretrace_end, 1.0);
  EXPECT_DOUBLE_EQ(settings_of("max_sample -3").max_sample, -3.0);
}

// POV-Ray reads the switches as `(int)F != 0`: a fraction below 1 is off, any negative integer on.
TEST(RadiositySettings, SwitchesTruncateTheirValue) {
  const RadiositySettings s = settings_of("always_sample 0.5 normal -1 media off subsurface 2");
  EXPECT_FALSE(s.always_sample);
  EXPECT_TRUE(s.normal);
  EXPECT_FALSE(s.media);
  EXPECT_TRUE(s.subsurface);
}

// Blocks in several global_settings (and several blocks in one) edit the same settings; the first block's keyword
// is where the scene turns radiosity on.
TEST(RadiositySettings, LaterBlocksEditTheSameSettings) {
  const SceneDescription s = parse(
      "#version 3.7;\nglobal_settings { radiosity { count 100 brightness 2 } }\n"
      "global_settings { radiosity { count 300 } radiosity { error_bound 1 } }\n");
  ASSERT_TRUE(s.radiosity);
  EXPECT_EQ(s.radiosity->count, 300);
  EXPECT_DOUBLE_EQ(s.radiosity->brightness, 2.0);
  EXPECT_DOUBLE_EQ(s.radiosity->error_bound, 1.0);
  EXPECT_EQ(s.radiosity->loc.line, 2);
}

// load_file and save_file are command-line options in 3.7: the string is read and ignored, with a warning.
TEST(RadiositySettings, FileItemsAreReadAndIgnoredWithAWarning) {
  Messages m;
  const RadiositySettings s = settings_of("load_file \"a.rca\" save_file concat(\"b\", \".rca\") count 60", &m);
  EXPECT_EQ(s.count, 60);
  ASSERT_EQ(m.items.size(), 2u) << m.joined();
  EXPECT_NE(m.items[0].find("test.pov:2:31: warning: Possible error: In POV-Ray 3.7 and later 'load_file'"),
            std::string::npos)
      << m.items[0];
  EXPECT_NE(m.items[1].find("'save_file' setting here is ignored"), std::string::npos) << m.items[1];
}

TEST(RadiositySettings, OldVersionScenesAreToldTheBlockTurnsRadiosityOn) {
  Messages m;
  parse("#version 3.1;\nglobal_settings { radiosity { } radiosity { } }\n", &m);
  ASSERT_EQ(m.items.size(), 1u) << m.joined();   // once: only the block that turns radiosity on
  EXPECT_NE(m.items[0].find("test.pov:2:19: warning: In POV-Ray 3.5 and later a radiosity{}-block"),
            std::string::npos)
      << m.items[0];
  Messages none;
  parse("#version 3.5;\nglobal_settings { radiosity { } }\n", &none);
  EXPECT_TRUE(none.items.empty()) << none.joined();
}

// ---- the minimum_reuse/maximum_reuse fix-up (pov: parse.cpp, end of Parse) ----

TEST(RadiosityReuse, DefaultMinimumIsLoweredBelowAWrittenMaximum) {
  Messages m;
  const RadiositySettings s = settings_of("maximum_reuse 0.02", &m);
  EXPECT_DOUBLE_EQ(s.maximum_reuse, 0.02);
  EXPECT_DOUBLE_EQ(s.minimum_reuse, 0.01);
  ASSERT_EQ(m.items.size(), 1u) << m.joined();
  EXPECT_NE(m.items[0].find("test.pov:2:31: warning: Radiosity maximum_reuse should be significantly larger than "
                            "minimum_reuse. Decreasing minimum_reuse to 0.010000 instead of the default."),
            std::string::npos)
      << m.items[0];
}

TEST(RadiosityReuse, DefaultMaximumIsRaisedAboveAWrittenMinimum) {
  Messages m;
  const RadiositySettings s = settings_of("minimum_reuse 0.15", &m);
  EXPECT_DOUBLE_EQ(s.minimum_reuse, 0.15);
  EXPECT_DOUBLE_EQ(s.maximum_reuse, 0.3);
  ASSERT_EQ(m.items.size(), 1u) << m.joined();
  EXPECT_NE(m.items[0].find("test.pov:2:31: warning: Radiosity maximum_reuse should be significantly larger than "
                            "minimum_reuse. Increasing maximum_reuse to 0.300000 instead of the default."),
            std::string::npos)
      << m.items[0];
}

TEST(RadiosityReuse, BothWrittenCloseTogetherOnlyWarn) {
  Messages m;
  const RadiositySettings s = settings_of("minimum_reuse 0.1 maximum_reuse 0.15", &m);
  EXPECT_DOUBLE_EQ(s.minimum_reuse, 0.1);
  EXPECT_DOUBLE_EQ(s.maximum_reuse, 0.15);
  ASSERT_EQ(m.items.size(), 1u) << m.joined();
  EXPECT_NE(m.items[0].find("test.pov:2:49: warning: Radiosity maximum_reuse should be significantly larger"),
            std::string::npos)
      << m.items[0];
}

TEST(RadiosityReuse, HalfOrMoreApartIsQuiet) {
  Messages m;
  const RadiositySettings s = settings_of("minimum_reuse 0.1 maximum_reuse 0.2", &m);
  EXPECT_DOUBLE_EQ(s.minimum_reuse, 0.1);
  EXPECT_DOUBLE_EQ(s.maximum_reuse, 0.2);
  EXPECT_TRUE(m.items.empty()) << m.joined();
}

// ---- errors: position, line, caret, POV-Ray's message ----

struct RadiosityError {
  std::string name;
  std::string text;
  int line, column;
  std::string fragment;
};

class RadiosityErrors : public ::testing::TestWithParam<RadiosityError> {};

std::string line_of(const std::string& text, int line) {
  std::size_t begin = 0;
  for (int l = 1; l < line && begin != std::string::npos; ++l) {
    begin = text.find('\n', begin);
    if (begin != std::string::npos) ++begin;
  }
  return begin == std::string::npos ? std::string() : text.substr(begin, text.find('\n', begin) - begin);
}

TEST_P(RadiosityErrors, LocationCaretAndMessage) {
  const RadiosityError& c = GetParam();
  const ParseError e = parse_error(c.text);
  EXPECT_EQ(e.location().line, c.line) << e.what();
  EXPECT_EQ(e.location().column, c.column) << e.what();
  EXPECT_NE(e.bare_message().find(c.fragment), std::string::npos) << e.bare_message();
  const std::string expected = "test.pov:" + std::to_string(c.line) + ":" + std::to_string(c.column) +
                               ": error: " + e.bare_message() + "\n" + line_of(c.text, c.line) + "\n" +
                               std::string(static_cast<std::size_t>(c.column - 1), ' ') + "^";
  EXPECT_EQ(std::string(e.what()), expected);
}

// Line 2 is `global_settings { radiosity { ITEMS } }`: the items start at column 31.
RadiosityError range(std::string name, const std::string& items, int column, std::string fragment) {
  return RadiosityError{std::move(name), with_block(items), 2, column, std::move(fragment)};
}

INSTANTIATE_TEST_SUITE_P(
    Ranges, RadiosityErrors,
    ::testing::Values(
        range("AdcBailoutZero", "adc_bailout 0", 43, "ADC Bailout must be a positive number (found 0)"),
        range("BrightnessNegative", "brightness -1", 42, "Radiosity brightness must be a positive number (found -1)"),
        range("CountZero", "count 0", 37, "Radiosity count must be a positive number (found 0)"),
        range("CountFraction", "count 0.9", 37,
              "Radiosity count must be a positive number (found 0.9, which counts as 0)"),
        range("CountAbovePool", "count 10, 5", 41,
              "Radiosity count can not be more than direction pool size (count 2nd value) (found 5); count is 10"),
        range("CountAbovePoolWithoutComma", "count 10 5", 40, "can not be more than direction pool size"),
        range("ErrorBoundZero", "error_bound 0", 43, "Radiosity error bound must be a positive number (found 0)"),
        range("GrayThresholdAbove", "gray_threshold 1.5", 46,
              "Radiosity gray threshold must be from 0.0 to 1.0 (found 1.5)"),
        range("GrayThresholdBelow", "gray_threshold -0.1", 46, "must be from 0.0 to 1.0 (found -0.1)"),
        range("LowErrorFactorZero", "low_error_factor 0", 48, "Radiosity low error factor must be a positive number"),
        range("MaximumReuseZero", "maximum_reuse 0", 45, "Radiosity maximum reuse must be a positive number"),
        range("MinimumReuseNegative", "minimum_reuse -0.01", 45,
              "Radiosity minimum reuse can not be a negative number (found -0.01)"),
        range("NearestCountZero", "nearest_count 0", 45,
              "Radiosity nearest count must be a value from 1 to 20 (found 0)"),
        range("NearestCountAbove", "nearest_count 21", 45, "must be a value from 1 to 20 (found 21)"),
        range("AdaptiveNotBelowNearestCount", "nearest_count 5, 5", 48,
              "Radiosity nearest count for adaptive pretrace must be non-negative and smaller than general nearest "
              "count (found 5); nearest count is 5"),
        range("AdaptiveNegative", "nearest_count 5, -1", 48, "must be non-negative and smaller"),
        range("RecursionLimitZero", "recursion_limit 0", 47,
              "Radiosity recursion limit must be in the range 1 to 20 (found 0)"),
        range("RecursionLimitAbove", "recursion_limit 21", 47, "in the range 1 to 20 (found 21)"),
        range("PretraceStartZero", "pretrace_start 0", 46,
              "Radiosity pretrace start must be greater than 0 and no higher than 1 (found 0)"),
        range("PretraceStartAbove", "pretrace_start 1.5", 46, "no higher than 1 (found 1.5)"),
        range("PretraceEndZero", "pretrace_end 0", 44,
              "Radiosity pretrace end must be greater than 0 and no higher than 1 (found 0)")),
    [](const auto& p) { return p.param.name; });

INSTANTIATE_TEST_SUITE_P(
    Syntax, RadiosityErrors,
    ::testing::Values(
        // POV-Ray 3.7 knows no other item (3.1's distance_maximum, radius… end the block there).
        range("UnknownItem", "distance_maximum 3", 31, "expected a radiosity setting (adc_bailout, always_sample"),
        range("SwitchNeedsAValue", "always_sample", 45, "found '}'"),
        RadiosityError{"NoBrace", "#version 3.7;\nglobal_settings { radiosity count 5 }\n", 2, 29,
                       "expected '{' after 'radiosity'"},
        RadiosityError{"AtTheTopLevel", "#version 3.7;\nradiosity { }\n", 1 + 1, 1,
                       "(radiosity { } is written inside global_settings { })"},
        RadiosityError{"ObjectImportanceZero", "#version 3.7;\nsphere { 0, 1 radiosity { importance 0 } }\n", 2, 38,
                       "Radiosity importance must be greater than 0.0 and at most 1.0 (found 0)"},
        RadiosityError{"DefaultImportanceAbove", "#version 3.7;\n#default { radiosity { importance 1.5 } }\n", 2, 35,
                       "Radiosity importance must be greater than 0.0 and at most 1.0 (found 1.5)"},
        RadiosityError{"ObjectSettingIsNoImportance", "#version 3.7;\nsphere { 0, 1 radiosity { count 5 } }\n", 2,
                       27, "expected importance or '}' in radiosity { }"}),
    [](const auto& p) { return p.param.name; });

// POV-Ray checks these once the scene is parsed (no position of its own): povtrace points at the item written.
INSTANTIATE_TEST_SUITE_P(
    AfterTheParse, RadiosityErrors,
    ::testing::Values(
        range("PretraceStartBelowDefaultEnd", "pretrace_start 0.02", 31,
              "Radiosity pretrace end must be smaller than or equal to pretrace start (pretrace_end 0.04, "
              "pretrace_start 0.02)"),
        range("PretraceEndAboveDefaultStart", "pretrace_end 0.1", 31, "(pretrace_end 0.1, pretrace_start 0.08)"),
        range("PretraceEndAboveStart", "pretrace_end 0.5 pretrace_start 0.2", 31,
              "(pretrace_end 0.5, pretrace_start 0.2)"),
        range("MinimumReuseEqualsMaximum", "minimum_reuse 0.1 maximum_reuse 0.1", 49,
              "Radiosity maximum_reuse must be larger than minimum_reuse (maximum_reuse 0.1; minimum_reuse 0.1, "
              "written at test.pov:2:31)"),
        RadiosityError{"ReuseAcrossBlocks",
                       "#version 3.7;\nglobal_settings { radiosity { minimum_reuse 0.3 } }\n"
                       "global_settings { radiosity { maximum_reuse 0.2 } }\n",
                       3, 31, "minimum_reuse 0.3, written at test.pov:2:31"}),
    [](const auto& p) { return p.param.name; });

// ---- radiosity importance (pov: parse.cpp Parse_Object_Mods, Parse_Default, Post_Process) ----

TEST(RadiosityImportance, ObjectsKeepWhatTheyWrite) {
  const SceneDescription s = parse(
      "#version 3.7;\nsphere { 0, 1 radiosity { importance 0.25 } }\nsphere { 0, 1 radiosity { } }\n"
      "sphere { 0, 1 radiosity { importance 0.5 importance 0.75 } }\n");
  ASSERT_EQ(s.objects.size(), 3u);
  EXPECT_EQ(s.objects[0].radiosity_importance, 0.25);
  EXPECT_FALSE(s.objects[1].radiosity_importance);
  EXPECT_EQ(s.objects[2].radiosity_importance, 0.75);
  EXPECT_FALSE(s.objects[0].unsupported);   // importance alone no longer stops the object
}

// A top-level object without an importance reads the #default in force at the end of the parse (POV-Ray reads
// defaultImportance when rendering), however early it was placed.
TEST(RadiosityImportance, TopLevelObjectsReadTheLastDefault) {
  const SceneDescription s = parse(
      "#version 3.7;\nsphere { 0, 1 }\n#default { radiosity { importance 0.5 } }\nsphere { 0, 1 }\n"
      "#default { radiosity { importance 0.2 } finish { ambient 0 } }\n#default { radiosity { } }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_FALSE(s.objects[0].radiosity_importance);
  EXPECT_FALSE(s.objects[1].radiosity_importance);
  EXPECT_DOUBLE_EQ(s.radiosity_default_importance, 0.2);
}

// CSG children without one take the parent's, or the #default in force when the top-level object is placed.
TEST(RadiosityImportance, CsgChildrenAreResolvedWhenPlaced) {
  const SceneDescription s = parse(
      "#version 3.7;\n#default { radiosity { importance 0.5 } }\n"
      "union { sphere { 0, 1 } sphere { x, 1 radiosity { importance 0.3 } } }\n"
      "union { sphere { 0, 1 } union { sphere { x, 1 } sphere { y, 1 } radiosity { importance 0.6 } } "
      "radiosity { importance 0.9 } }\n"
      "#declare U = union { sphere { 0, 1 } sphere { x, 1 } }\n"
      "#default { radiosity { importance 0.1 } }\n"
      "object { U }\n");
  ASSERT_EQ(s.objects.size(), 3u);
  const auto& first = std::get<Csg>(s.objects[0].shape).children;
  EXPECT_FALSE(s.objects[0].radiosity_importance);
  EXPECT_EQ(first[0].radiosity_importance, 0.5);
  EXPECT_EQ(first[1].radiosity_importance, 0.3);
  const auto& second = std::get<Csg>(s.objects[1].shape).children;
  EXPECT_EQ(second[0].radiosity_importance, 0.9);
  EXPECT_EQ(second[1].radiosity_importance, 0.6);
  for (const Object& grandchild : std::get<Csg>(second[1].shape).children)
    EXPECT_EQ(grandchild.radiosity_importance, 0.6);
  // Declared under 0.5, placed under 0.1: the children take the default at placement.
  for (const Object& child : std::get<Csg>(s.objects[2].shape).children) EXPECT_EQ(child.radiosity_importance, 0.1);
  EXPECT_DOUBLE_EQ(s.radiosity_default_importance, 0.1);
}

TEST(RadiosityImportance, CopiesKeepItAndMayChangeIt) {
  const SceneDescription s = parse(
      "#version 3.7;\n#declare S = sphere { 0, 1 radiosity { importance 0.4 } }\n"
      "object { S }\nobject { S radiosity { importance 0.8 } }\n");
  ASSERT_EQ(s.objects.size(), 2u);
  EXPECT_EQ(s.objects[0].radiosity_importance, 0.4);
  EXPECT_EQ(s.objects[1].radiosity_importance, 0.8);
}

// A looks_like object is the light's child: it takes the light's importance — the CSG parent's, or the default.
TEST(RadiosityImportance, LooksLikeObjectsTakeTheDefaultOrTheCsgParents) {
  const SceneDescription s = parse(
      "#version 3.7;\n#default { radiosity { importance 0.5 } }\n"
      "light_source { 0, 1 looks_like { sphere { 0, 1 } } }\n"
      "union { sphere { 0, 1 } light_source { 0, 1 looks_like { sphere { 0, 1 } } } "
      "radiosity { importance 0.7 } }\n"
      "light_source { 0, 1 looks_like { sphere { 0, 1 radiosity { importance 0.2 } } } }\n");
  ASSERT_EQ(s.objects.size(), 4u);
  EXPECT_EQ(s.objects[0].radiosity_importance, 0.5);   // the first light's looks_like
  int found = 0;
  for (const Object& o : s.objects) {
    if (std::holds_alternative<Csg>(o.shape)) continue;
    found += o.radiosity_importance == 0.7 ? 1 : 0;
  }
  EXPECT_EQ(found, 1);                                  // the light inside the union
  EXPECT_EQ(s.objects[3].radiosity_importance, 0.2);
}

// ---- what the renderer will need besides the settings ----

// The radiosity term uses diffuse and diffuse_back before the block's `albedo` rescaling; a finish copied from an
// identifier starts from that finish's rescaled values (POV-Ray's RawDiffuse is set at the end of every block).
TEST(RadiosityFinish, RawDiffuseIsBeforeTheBlocksAlbedo) {
  const SceneDescription s = parse(
      "#version 3.7;\n#declare F = finish { diffuse albedo 0.5, 0.2 brilliance 3 }\n"
      "sphere { 0, 1 finish { F } }\nsphere { 0, 1 finish { F diffuse 0.7 } }\n"
      "sphere { 0, 1 finish { diffuse albedo 0.5, 0.2 brilliance 3 } }\nsphere { 0, 1 }\n");
  ASSERT_EQ(s.objects.size(), 4u);
  const Finish& copied = s.objects[0].texture->layers.back().finish;
  EXPECT_DOUBLE_EQ(copied.diffuse, 1.0);
  EXPECT_DOUBLE_EQ(copied.diffuse_raw, 1.0);
  EXPECT_DOUBLE_EQ(copied.diffuse_back_raw, 0.4);
  const Finish& rewritten = s.objects[1].texture->layers.back().finish;
  EXPECT_DOUBLE_EQ(rewritten.diffuse_raw, 0.7);
  const Finish& own = s.objects[2].texture->layers.back().finish;
  EXPECT_DOUBLE_EQ(own.diffuse, 1.0);
  EXPECT_DOUBLE_EQ(own.diffuse_back, 0.4);
  EXPECT_DOUBLE_EQ(own.diffuse_raw, 0.5);
  EXPECT_DOUBLE_EQ(own.diffuse_back_raw, 0.2);
  const Finish& plain = s.objects[3].texture->layers.back().finish;
  EXPECT_DOUBLE_EQ(plain.diffuse_raw, 0.6);
  EXPECT_DOUBLE_EQ(plain.diffuse_back_raw, 0.0);
}

// POV-Ray drops `ambient` under radiosity only when the effective version is 3.7 or later, and a scene without
// any #version (or +MV) counts as 3.62 there.
TEST(RadiosityAmbient, EffectiveLanguageVersion) {
  const SceneDescription none = parse("global_settings { radiosity { } }\n");
  EXPECT_FALSE(none.language_version_set);
  EXPECT_EQ(none.language_version, 370);
  EXPECT_EQ(none.effective_language_version(), 362);
  const SceneDescription late = parse("sphere { 0, 1 }\n#version 3.7;\n");
  EXPECT_TRUE(late.language_version_set);   // any #version sets it, even after the first statement
  EXPECT_EQ(late.effective_language_version(), 370);
  const SceneDescription legacy = parse("#version 3.6;\n");
  EXPECT_EQ(legacy.effective_language_version(), 360);
  ParseOptions mv;
  mv.initial_language_version = 370;
  mv.message_sink = [](const std::string&) {};
  EXPECT_EQ(parse_scene_text("sphere { 0, 1 }\n", "test.pov", mv).effective_language_version(), 370);
}

}  // namespace
}  // namespace povtrace::test

// mandel, julia, magnet, slope, aoi, pigment_pattern and a pattern's own noise_generator as the parser records them (POV-Ray 3.7's
// Parse_Pattern: defaults, resets, limits, errors and warnings).
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Pigment& pigment_of(const SceneDescription& s, std::size_t i = 0) {
  return s.objects.at(i).texture->layers.back().pigment;
}
SceneDescription scene(const std::string& body, Messages* m = nullptr) { return parse("#version 3.7;\n" + body, m); }
std::string error_of(const std::string& body) { return parse_error("#version 3.7;\n" + body).bare_message(); }

TEST(FractalPatternParse, MandelDefaultsAndParameters) {
  const SceneDescription s = scene(
      "sphere { 0, 1 pigment { mandel 49.9 } }\n"
      "sphere { 0, 1 pigment { mandel 30 exponent 5 exterior 7, 4 interior 6, 0.5 } }\n");
  const FractalParams& a = pigment_of(s, 0).fractal;
  EXPECT_EQ(pigment_of(s, 0).pattern, PatternKind::mandel);
  EXPECT_EQ(a.iterations, 49);   // (int) of the float, as POV-Ray stores it
  EXPECT_EQ(a.exponent, 2);
  EXPECT_EQ(a.exterior_type, 1);
  EXPECT_EQ(a.interior_type, 0);
  EXPECT_EQ(a.exterior_factor, 1.0);
  EXPECT_EQ(a.interior_factor, 1.0);
  EXPECT_FALSE(a.julia);
  EXPECT_EQ(a.magnet, 0);
  const FractalParams& b = pigment_of(s, 1).fractal;
  EXPECT_EQ(b.exponent, 5);
  EXPECT_EQ(b.exterior_type, 7);
  EXPECT_EQ(b.exterior_factor, 4.0);
  EXPECT_EQ(b.interior_type, 6);
  EXPECT_EQ(b.interior_factor, 0.5);
}

TEST(FractalPatternParse, JuliaAndMagnetForms) {
  const SceneDescription s = scene(
      "sphere { 0, 1 pigment { julia <0.3, -0.4>, 20 exponent 3 } }\n"
      "sphere { 0, 1 pigment { julia 0.25 10 } }\n"
      "sphere { 0, 1 pigment { magnet 2 mandel 15 } }\n"
      "sphere { 0, 1 pigment { magnet 1 julia <1, 0.5>, 12 } }\n");
  const FractalParams& j = pigment_of(s, 0).fractal;
  EXPECT_EQ(pigment_of(s, 0).pattern, PatternKind::julia);
  EXPECT_TRUE(j.julia);
  EXPECT_EQ(j.coord_u, 0.3);
  EXPECT_EQ(j.coord_v, -0.4);
  EXPECT_EQ(j.iterations, 20);
  EXPECT_EQ(j.exponent, 3);
  const FractalParams& k = pigment_of(s, 1).fractal;   // a float promotes to <f, f>; the comma is optional
  EXPECT_EQ(k.coord_u, 0.25);
  EXPECT_EQ(k.coord_v, 0.25);
  EXPECT_EQ(k.iterations, 10);
  const FractalParams& m = pigment_of(s, 2).fractal;
  EXPECT_EQ(pigment_of(s, 2).pattern, PatternKind::magnet);
  EXPECT_EQ(m.magnet, 2);
  EXPECT_FALSE(m.julia);
  EXPECT_EQ(m.iterations, 15);
  const FractalParams& n = pigment_of(s, 3).fractal;
  EXPECT_EQ(n.magnet, 1);
  EXPECT_TRUE(n.julia);
  EXPECT_EQ(n.coord_u, 1.0);
  EXPECT_EQ(n.coord_v, 0.5);
  EXPECT_EQ(n.iterations, 12);
}

TEST(FractalPatternParse, ExponentOutOfRangeWarnsAndUsesTwo) {
  Messages m;
  const SceneDescription s = scene("sphere { 0, 1 pigment { mandel 10 exponent 34 } }\n", &m);
  EXPECT_EQ(pigment_of(s).fractal.exponent, 2);
  EXPECT_NE(m.joined().find("Supported exponents are 2 to 33"), std::string::npos) << m.joined();
}

TEST(FractalPatternParse, Errors) {
  EXPECT_NE(error_of("sphere { 0, 1 pigment { magnet 3 mandel 10 } }\n").find("Valid types are 1 and 2"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { magnet 1 gradient 10 } }\n").find("'mandel' and 'julia'"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { mandel 10 exterior 9, 1 } }\n").find("Valid types are 0 to 8"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { mandel 10 interior 7, 1 } }\n").find("Valid types are 0 to 6"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { bozo exterior 1, 1 } }\n").find("mandel, julia or magnet"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { magnet 1 mandel 10 exponent 3 } }\n").find("mandel or julia"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { mandel -1 } }\n").find("must not be negative"), std::string::npos);
  // POV-Ray divides by zero (and crashes) on these; povtrace says why at the factor.
  const ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { mandel 10 exterior 7, 0.5 } }\n");
  EXPECT_NE(e.bare_message().find("must not be 0"), std::string::npos) << e.what();
  EXPECT_EQ(e.location().column, 47) << e.what();
  EXPECT_NE(error_of("sphere { 0, 1 pigment { mandel 10 exterior 8, -1 } }\n").find("must not be 0"),
            std::string::npos);
}

TEST(SlopePatternParse, SimpleAndBlockForms) {
  const SceneDescription s = scene(
      "sphere { 0, 1 pigment { slope <0, 2, 0> } }\n"
      "sphere { 0, 1 pigment { slope { <1, 1, 0>, 0.2, 0.7 } } }\n"
      "sphere { 0, 1 pigment { slope { y altitude <0, 3, 0>, 1, 5 } } }\n"
      "sphere { 0, 1 pigment { slope { point_at <1, 2, 3> } } }\n");
  const SlopeParams& a = pigment_of(s, 0).slope;
  EXPECT_EQ(pigment_of(s, 0).pattern, PatternKind::slope);
  EXPECT_EQ(a.direction.y, 1.0);
  EXPECT_EQ(a.slope_axis, 2);   // exactly +y: POV-Ray's shortcut
  EXPECT_EQ(a.slope_weight, 1.0);
  EXPECT_EQ(a.altitude_weight, 0.0);
  const SlopeParams& b = pigment_of(s, 1).slope;
  EXPECT_EQ(b.slope_axis, 0);
  EXPECT_NEAR(b.direction.x, std::sqrt(0.5), 1e-15);
  EXPECT_EQ(b.slope_low, 0.2);
  EXPECT_EQ(b.slope_range, 0.7 - 0.2);   // high is kept as high − low
  const SlopeParams& c = pigment_of(s, 2).slope;
  EXPECT_EQ(c.slope_weight, 0.25);        // lengths 1 and 3
  EXPECT_EQ(c.altitude_weight, 0.75);
  EXPECT_EQ(c.altitude_axis, 2);
  EXPECT_EQ(c.altitude_low, 1.0);
  EXPECT_EQ(c.altitude_range, 4.0);
  const SlopeParams& d = pigment_of(s, 3).slope;
  EXPECT_TRUE(d.point_at);
  EXPECT_EQ(d.direction.z, 3.0);   // the point itself, not normalised
  EXPECT_EQ(d.slope_weight, 1.0);
  EXPECT_EQ(d.altitude_weight, 0.0);
}

TEST(SlopePatternParse, ZeroRangeWarnsAndErrors) {
  Messages m;
  const SceneDescription s = scene("sphere { 0, 1 pigment { slope { y, 0.5, 0.5 } } }\n", &m);
  EXPECT_EQ(pigment_of(s).slope.slope_range, 0.0);
  EXPECT_EQ(pigment_of(s).slope.slope_low, 0.0);
  EXPECT_NE(m.joined().find("Zero slope range, ignoring."), std::string::npos) << m.joined();
  EXPECT_NE(error_of("sphere { 0, 1 pigment { slope 0 } }\n").find("Zero length for both slope and gradient"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { slope { point_at y altitude y } } }\n")
                .find("'altitude' cannot be used with 'point_at'"),
            std::string::npos);
}

TEST(SurfacePatternParse, AoiAndTexturePatterns) {
  const SceneDescription s = scene(
      "sphere { 0, 1 pigment { aoi } }\n"
      "sphere { 0, 1 texture { slope y texture_map { [0 pigment { rgb 1 }] [1 pigment { rgb 0 }] } } }\n"
      "sphere { 0, 1 normal { mandel 20 0.5 } }\n");
  EXPECT_EQ(pigment_of(s, 0).pattern, PatternKind::aoi);
  ASSERT_TRUE(s.objects[1].texture->patterned());
  EXPECT_EQ(s.objects[1].texture->pattern->pattern.pattern, PatternKind::slope);
  const Normal& n = *s.objects[2].texture->layers.back().normal;
  EXPECT_EQ(n.pattern.pattern, PatternKind::mandel);
  EXPECT_EQ(n.pattern.fractal.iterations, 20);
  EXPECT_EQ(n.amount, 0.5);
}

TEST(PigmentPatternParse, APigmentOfItsOwnFromPlainBlack) {
  const SceneDescription s = scene(
      "#default { pigment { rgb <1, 0, 0> } }\n"
      "#declare P = pigment { checker rgb 1, rgb 0 }\n"
      "sphere { 0, 1 pigment { pigment_pattern { P scale 2 } color_map { [0 rgb 0] [1 rgb 1] } } }\n"
      "sphere { 0, 1 pigment { pigment_pattern { } } }\n"
      "sphere { 0, 1 normal { pigment_pattern { bozo } 0.7 } }\n");
  const Pigment& a = pigment_of(s, 0);
  EXPECT_EQ(a.pattern, PatternKind::pigment_pattern);
  ASSERT_TRUE(a.pattern_pigment);
  EXPECT_EQ(a.pattern_pigment->pattern, PatternKind::checker);
  EXPECT_EQ(a.pattern_pigment->world_from_pattern.m[0][0], 2.0);   // its transforms are its own
  EXPECT_EQ(a.world_from_pattern.m[0][0], 1.0);
  ASSERT_EQ(a.entries.size(), 2u);
  const Pigment& b = pigment_of(s, 1);   // not the #default pigment: POV-Ray's Create_Pigment is black
  ASSERT_TRUE(b.pattern_pigment);
  EXPECT_EQ(b.pattern_pigment->pattern, PatternKind::solid);
  EXPECT_EQ(b.pattern_pigment->colour.r, 0.0);
  const Normal& n = *s.objects[2].texture->layers.back().normal;
  EXPECT_EQ(n.pattern.pattern, PatternKind::pigment_pattern);
  EXPECT_EQ(n.amount, 0.7);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { pigment_pattern rgb 1 } }\n").find("'{'"), std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { pigment_pattern { pavement } } }\n")
                .find("unsupported: the pigment item 'pavement'"),
            std::string::npos);
}

TEST(PatternNoiseGenerator, OwnGeneratorOrsIntoTheFlags) {
  const SceneDescription s = scene(
      "sphere { 0, 1 pigment { bozo } }\n"
      "sphere { 0, 1 pigment { bozo noise_generator 3 } }\n"
      "sphere { 0, 1 pigment { bozo noise_generator 1 noise_generator 2 } }\n"
      "sphere { 0, 1 normal { bumps 0.5 noise_generator 1.9 } }\n");
  EXPECT_EQ(pigment_of(s, 0).noise_generator, 0);   // the scene's
  EXPECT_EQ(pigment_of(s, 1).noise_generator, 3);
  EXPECT_EQ(pigment_of(s, 2).noise_generator, 3);   // POV-Ray ORs the values into its flags
  EXPECT_EQ(s.objects[3].texture->layers.back().normal->pattern.noise_generator, 1);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { bozo noise_generator 4 } }\n").find("must be 0, 1, 2, or 3"),
            std::string::npos);
  EXPECT_NE(error_of("sphere { 0, 1 pigment { bozo noise_generator -1 } }\n").find("must be 0, 1, 2, or 3"),
            std::string::npos);
}

}  // namespace
}  // namespace povtrace::test

// Pigment patterns, maps and modifiers as the parser records them (povray-sdl-and-geometry.md §11).
#include <gtest/gtest.h>

#include "parse_helpers.hpp"

namespace povtrace::test {
namespace {

const Pigment& pigment_of(const SceneDescription& s, std::size_t i = 0) {
  return s.objects.at(i).texture->layers.back().pigment;
}
SceneDescription scene(const std::string& body) { return parse("#version 3.7;\n" + body); }
double single(double d) { return static_cast<double>(static_cast<float>(d)); }

TEST(PigmentParse, ColourMapSyntaxes) {
  const SceneDescription scene_p = scene(
      "#declare M = color_map { [0.1 rgb 1] [0.3, rgbt <0, 0, 1, 0.5>] [0.5, 0.9 color rgb 0 color rgb <1, 0, 0>] }\n"
      "sphere { 0, 1 pigment { gradient y colour_map { M } } }\n");
  const Pigment& p = pigment_of(scene_p);
  EXPECT_EQ(p.pattern, PatternKind::gradient);
  ASSERT_EQ(p.entries.size(), 4u);
  EXPECT_EQ(p.entries[0].value, single(0.1));   // map values are single precision, as in POV-Ray
  EXPECT_EQ(p.entries[1].colour.t, 0.5);
  EXPECT_EQ(p.entries[2].value, 0.5);           // the old two-colour entry becomes two entries
  EXPECT_EQ(p.entries[3].value, single(0.9));
  EXPECT_EQ(p.entries[3].colour.r, 1.0);
}

TEST(PigmentParse, PigmentMapAndListEntries) {
  const SceneDescription s = scene(
      "#declare P = pigment { rgb <0, 1, 0> }\n"
      "sphere { 0, 1 pigment { bozo pigment_map { [0 P] [1 checker rgb 1, rgb 0 scale 2] } } }\n"
      "sphere { 0, 1 pigment { hexagon pigment { P } } }\n");
  const Pigment& a = pigment_of(s, 0);
  ASSERT_EQ(a.entries.size(), 2u);
  ASSERT_TRUE(a.entries[1].pigment);
  EXPECT_EQ(a.entries[1].pigment->pattern, PatternKind::checker);
  EXPECT_EQ(a.entries[0].pigment->colour.g, 1.0);
  const Pigment& h = pigment_of(s, 1);
  ASSERT_EQ(h.entries.size(), 3u);   // the two missing entries are the #default pigment
  EXPECT_EQ(h.entries[0].pigment->colour.g, 1.0);
  EXPECT_EQ(h.entries[2].value, 2.0);
  EXPECT_EQ(h.frequency, 0.0);       // list patterns skip the wave step
}

TEST(PigmentParse, ModifiersAndDefaults) {
  const SceneDescription scene_p = scene(
      "sphere { 0, 1 pigment { marble turbulence 0.5 octaves 20 omega 0.3 frequency 3 phase 0.1 poly_wave 2 } }\n");
  const Pigment& p = pigment_of(scene_p);
  EXPECT_EQ(p.pattern, PatternKind::marble);
  ASSERT_TRUE(p.turbulence);
  EXPECT_EQ(p.turbulence->amount.y, 0.5);
  EXPECT_EQ(p.turbulence->octaves, 10);   // clamped as POV-Ray does
  EXPECT_EQ(p.turbulence->omega, 0.3f);   // single precision, as POV-Ray keeps omega and lambda
  EXPECT_EQ(p.turbulence->lambda, 2.0);
  EXPECT_EQ(p.phase, single(0.1));
  EXPECT_EQ(p.wave, WaveType::poly);
  EXPECT_EQ(p.exponent, 2.0);
  const SceneDescription scene_w = scene("sphere { 0, 1 pigment { wood } }\n");
  const Pigment& w = pigment_of(scene_w);
  EXPECT_EQ(w.wave, WaveType::triangle);
  const SceneDescription scene_b = scene("sphere { 0, 1 pigment { brick mortar 0.2 } }\n");
  const Pigment& b = pigment_of(scene_b);
  EXPECT_EQ(b.mortar, single(0.2 - 2e-10));
  EXPECT_EQ(b.entries[1].colour.r, single(0.6));
}

TEST(PigmentParse, WarpsSplitTheTransformsInWrittenOrder) {
  const SceneDescription scene_p = scene(
      "sphere { 0, 1 pigment { bozo scale 2 warp { turbulence 0.4 octaves 3 } translate x } }\n");
  const Pigment& p = pigment_of(scene_p);
  ASSERT_EQ(p.warps.size(), 1u);
  EXPECT_EQ(p.warps[0].before, Matrix::scaling({2, 2, 2}));
  EXPECT_EQ(p.warps[0].turbulence.octaves, 3);
  EXPECT_EQ(p.world_from_pattern, Matrix::translation({1, 0, 0}));
  EXPECT_FALSE(p.turbulence);
}

TEST(PigmentParse, CopyAndModifyKeepsTheMap) {
  const SceneDescription scene_p = scene(
      "#declare P = pigment { gradient x color_map { [0 rgb 1] [1 rgb <1, 0, 0>] } }\n"
      "sphere { 0, 1 pigment { P onion frequency 2 } }\n");
  const Pigment& p = pigment_of(scene_p);
  EXPECT_EQ(p.pattern, PatternKind::onion);
  EXPECT_EQ(p.entries.size(), 2u);
  EXPECT_EQ(p.frequency, 2.0);
}

TEST(PigmentParse, Refusals) {
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { checker color_map { [0 rgb 1] } } }\n")
                .bare_message().find("cannot use color_map"), std::string::npos);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { bozo mortar 0.1 } }\n")
                .bare_message().find("non-brick"), std::string::npos);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { average } }\n")
                .bare_message().find("pigment_map"), std::string::npos);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { bozo warp { cylindrical planar } } }\n")
                .bare_message().find("closing the warp"), std::string::npos);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { bozo warp { planar x } } }\n")
                .bare_message().find("expected"), std::string::npos);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { gradient x pigment_map { [0 pavement] [1 rgb 1] } } }\n")
                .bare_message().find("unsupported: the pigment item 'pavement'"), std::string::npos);
}

// function { EXPRESSION } as a pattern (POV-Ray's Parse_Function): a float function of x, y, z.
TEST(PigmentParse, FunctionPattern) {
  const SceneDescription s = scene("#declare F = function(a, b, c) { a + b }\n"
                                   "sphere { 0, 1 pigment { function { F(x, y, z) * 2 } } }\n"
                                   "sphere { 0, 1 normal { function { x } 0.5 } }\n");
  const Pigment& p = pigment_of(s, 0);
  EXPECT_EQ(p.pattern, PatternKind::function);
  ASSERT_TRUE(p.function);
  EXPECT_FALSE(p.unsupported);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { function(a) { a } } }\n")
                .bare_message().find("'{' after 'function'"), std::string::npos);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { function { transform { scale 2 } } } }\n")
                .bare_message().find("a float function of x, y and z"), std::string::npos);
  // What povtrace cannot evaluate (a pattern function inside) is refused by name when the object is placed.
  EXPECT_NE(parse_error("#version 3.7;\n#declare G = function { pattern { agate } }\n"
                        "sphere { 0, 1 pigment { function { G(x, y, z) } } }\n")
                .bare_message().find("unsupported: a pattern of the pattern function"), std::string::npos);
}

// spiral1/spiral2 N: the arm count truncated to a short, and the triangle wave by default.
TEST(PigmentParse, Spirals) {
  const SceneDescription s = scene("sphere { 0, 1 pigment { spiral1 3.7 } }\nsphere { 0, 1 pigment { spiral2 -2 sine_wave } }\n");
  EXPECT_EQ(pigment_of(s, 0).pattern, PatternKind::spiral1);
  EXPECT_EQ(pigment_of(s, 0).arms, 3);
  EXPECT_EQ(pigment_of(s, 0).wave, WaveType::triangle);
  EXPECT_EQ(pigment_of(s, 1).pattern, PatternKind::spiral2);
  EXPECT_EQ(pigment_of(s, 1).arms, -2);
  EXPECT_EQ(pigment_of(s, 1).wave, WaveType::sine);
}

// quilted resets control0/control1 to 1 and the frequency to 0; the controls belong to quilted only.
TEST(PigmentParse, Quilted) {
  const SceneDescription s = scene("sphere { 0, 1 pigment { quilted control0 0.25 control1 0.1 } }\n"
                                   "sphere { 0, 1 normal { quilted 0.5 control1 2 } }\n");
  const Pigment& p = pigment_of(s, 0);
  EXPECT_EQ(p.pattern, PatternKind::quilted);
  EXPECT_EQ(p.control0, 0.25f);
  EXPECT_EQ(p.control1, 0.1f);
  EXPECT_EQ(p.frequency, 0.0);
  const Normal& n = *s.objects.at(1).texture->layers.back().normal;
  EXPECT_EQ(n.kind, NormalKind::quilted);
  EXPECT_EQ(n.pattern.control0, 1.0f);
  EXPECT_EQ(n.pattern.control1, 2.0f);
  EXPECT_NE(parse_error("#version 3.7;\nsphere { 0, 1 pigment { bozo control0 1 } }\n").bare_message().find(
                "cannot be used with this pattern"),
            std::string::npos);
}

TEST(PigmentParse, GlobalNoiseGenerator) {
  EXPECT_EQ(scene("global_settings { noise_generator 1 }\n").settings.noise_generator, 1);
  EXPECT_FALSE(scene("global_settings { }\n").settings.noise_generator);
  EXPECT_EQ(scene("global_settings { noise_generator 3.7 }\n").settings.noise_generator, 3);   // truncated
  EXPECT_NE(parse_error("#version 3.7;\nglobal_settings { noise_generator 4 }\n")
                .bare_message().find("must be 1, 2, or 3"), std::string::npos);
  EXPECT_NE(parse_error("#version 3.7;\nglobal_settings { noise_generator 0 }\n")
                .bare_message().find("must be 1, 2, or 3"), std::string::npos);
}

TEST(PigmentParse, CrackleParameters) {
  const SceneDescription s = scene(
      "sphere { 0, 1 pigment { crackle metric 1 form <1, 0.5, 0> offset 0.2 solid } }\n"
      "sphere { 0, 1 pigment { crackle } }\n");
  const CrackleParams& c = pigment_of(s, 0).crackle;
  EXPECT_EQ(c.metric, 1.0);
  EXPECT_EQ(c.form, (Vec3{1, 0.5, 0}));
  EXPECT_EQ(c.offset, 0.2);
  EXPECT_TRUE(c.solid);
  EXPECT_EQ(pigment_of(s, 1).crackle, CrackleParams{});
  EXPECT_EQ(pigment_of(s, 1).crackle.form, (Vec3{-1, 1, 0}));   // POV-Ray's default form
  const ParseError e = parse_error("#version 3.7;\nsphere { 0, 1 pigment { bozo metric 1 } }\n");
  EXPECT_NE(std::string(e.what()).find("non-crackle"), std::string::npos) << e.what();
}

TEST(PigmentParse, RepeatWarp) {
  const SceneDescription s = scene("sphere { 0, 1 pigment { onion scale 2 warp { repeat y*0.5 offset x flip <1, 0, 1> } } }\n");
  const Pigment& p = pigment_of(s);
  ASSERT_EQ(p.warps.size(), 1u);
  ASSERT_TRUE(p.warps[0].repeat);
  EXPECT_EQ(p.warps[0].repeat->axis, 1);
  EXPECT_EQ(p.warps[0].repeat->width, 0.5);
  EXPECT_EQ(p.warps[0].repeat->offset, (Vec3{1, 0, 0}));
  EXPECT_EQ(p.warps[0].repeat->flip, (Vec3{-1, 1, -1}));
  EXPECT_EQ(p.warps[0].before, Matrix::scaling({2, 2, 2}));   // the transform written before the warp
  EXPECT_NE(std::string(parse_error("#version 3.7;\nsphere { 0, 1 pigment { onion warp { repeat <1, 1, 0> } } }\n")
                            .what()).find("only repeat along 1 axis"), std::string::npos);
  EXPECT_NE(std::string(parse_error("#version 3.7;\nsphere { 0, 1 pigment { onion warp { repeat 0*x } } }\n")
                            .what()).find("no axis specified"), std::string::npos);
}

}  // namespace
}  // namespace povtrace::test

namespace povtrace::test {
namespace {
// The mapping warps and black_hole as Parse_Warp reads them: orientation normalised by its reciprocal length,
// planar's distance, and Check_BH_Parameters moving the centre up to the radius and growing the repeat vector.
TEST(PigmentParse, MappingAndBlackHoleWarps) {
  Messages m;
  const SceneDescription s = parse(
      "#version 3.7;\nsphere { 0, 1 pigment { bozo warp { planar x, 0.3 } warp { cylindrical orientation <0, 2, 0> "
      "dist_exp 1 } warp { toroidal major_radius 2 } warp { black_hole <0, 0, 0>, 0.5 falloff 3 repeat <0.5, 0, 0> "
      "turbulence <0.2, 0, 0> inverse } } }\n",
      &m);
  const Pigment& p = s.objects.at(0).texture->layers.back().pigment;
  ASSERT_EQ(p.warps.size(), 4u);
  ASSERT_TRUE(p.warps[0].mapping);
  EXPECT_EQ(p.warps[0].mapping->kind, MappingWarpKind::planar);
  EXPECT_EQ(p.warps[0].mapping->orientation, (Vec3{1, 0, 0}));
  EXPECT_EQ(p.warps[0].mapping->offset, 0.3);
  EXPECT_EQ(p.warps[1].mapping->orientation, (Vec3{0, 1, 0}));
  EXPECT_EQ(p.warps[1].mapping->dist_exp, 1.0);
  EXPECT_EQ(p.warps[2].mapping->major_radius, 2.0);
  ASSERT_TRUE(p.warps[3].black_hole);
  const BlackHoleWarp& h = *p.warps[3].black_hole;
  EXPECT_EQ(h.centre.x, 0.5);            // moved up to the radius on the repeated axis
  EXPECT_EQ(h.centre.y, 0.0);
  EXPECT_EQ(h.repeat_vector.x, 1.2);     // grown to the far side plus the jitter
  EXPECT_TRUE(h.inverse);
  EXPECT_EQ(h.falloff, 3.0);
  EXPECT_NE(m.joined().find("Black Hole repeat vector X too small; increased to 1.2"), std::string::npos)
      << m.joined();
}
}  // namespace
}  // namespace povtrace::test

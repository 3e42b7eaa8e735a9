// Pattern values at hand-computed points, the wave step, colour-map lookup, and statistical properties of the
// noise (which cannot match POV-Ray's point by point: its random table is not ours).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "runtime/noise.hpp"
#include "parser/parse_scene.hpp"
#include "renderer/pattern/pattern.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {
namespace {

double value_of(PatternKind kind, Vec3 p) {
  PatternParams params;
  params.kind = kind;
  return pattern_value(params, p);
}

TEST(Pattern, GradientIsTheProjectionFoldedAboveOne) {
  PatternParams g;
  g.kind = PatternKind::gradient;
  g.gradient = normalize(Vec3{1, 1, 0});
  EXPECT_NEAR(pattern_value(g, {0.5, 0.5, 7}), std::sqrt(0.5), 1e-15);
  g.gradient = {1, 0, 0};
  EXPECT_NEAR(pattern_value(g, {2.25, 0, 0}), 0.25, 1e-15);
  EXPECT_DOUBLE_EQ(pattern_value(g, {1.0, 0, 0}), 1.0);       // exactly 1 is kept
  EXPECT_DOUBLE_EQ(pattern_value(g, {-0.75, 0, 0}), -0.75);   // negatives are left to the wave step
}

TEST(Pattern, RadialIsTheAngleAroundY) {
  EXPECT_DOUBLE_EQ(value_of(PatternKind::radial, {0, 5, 1}), 0.75);    // atan2(0, 1) = 0
  EXPECT_DOUBLE_EQ(value_of(PatternKind::radial, {1, 0, 0}), 1.0);     // a quarter turn further
  EXPECT_DOUBLE_EQ(value_of(PatternKind::radial, {0, 0, -1}), 1.25);   // atan2(0, −1) = π
  EXPECT_DOUBLE_EQ(value_of(PatternKind::radial, {0.0005, 3, 0}), 0.25);   // on the axis
}

TEST(Pattern, DistancePatternsFallFromOneToZero) {
  EXPECT_NEAR(value_of(PatternKind::onion, {3, 4, 0}), 0.0, 1e-15);           // |p| = 5
  EXPECT_NEAR(value_of(PatternKind::onion, {0, 2.25, 0}), 0.25, 1e-15);
  EXPECT_DOUBLE_EQ(value_of(PatternKind::planar, {9, -0.25, 9}), 0.75);
  EXPECT_DOUBLE_EQ(value_of(PatternKind::boxed, {0.5, -0.75, 0.25}), 0.25);
  EXPECT_DOUBLE_EQ(value_of(PatternKind::spherical, {0.6, 0, 0.8}), 0.0);    // |p| = 1
  EXPECT_DOUBLE_EQ(value_of(PatternKind::spherical, {0, 2, 0}), 0.0);        // beyond 1
  EXPECT_NEAR(value_of(PatternKind::cylindrical, {0.3, 50, 0.4}), 0.5, 1e-15);
}

TEST(Pattern, LeopardIsTheSquaredMeanOfSines) {
  const double h = std::numbers::pi / 2;
  EXPECT_NEAR(value_of(PatternKind::leopard, {h, h, h}), 1.0, 1e-15);
  EXPECT_NEAR(value_of(PatternKind::leopard, {h, 0, 0}), 1.0 / 9.0, 1e-15);
}

TEST(Pattern, CheckerIsTheCellParity) {
  EXPECT_EQ(value_of(PatternKind::checker, {0.5, 0.5, 0.5}), 0.0);
  EXPECT_EQ(value_of(PatternKind::checker, {1.5, 0.5, 0.5}), 1.0);
  EXPECT_EQ(value_of(PatternKind::checker, {-0.5, 0.5, 0.5}), 1.0);
  EXPECT_EQ(value_of(PatternKind::checker, {1 - 1e-11, 0.5, 0.5}), 1.0);   // within ε below 1 counts as above
}

TEST(Pattern, HexagonColoursRepeatEveryThreeAlongAColumn) {
  // Centres at (1.5 i, 0.866 j), i + j even; colour (j + 3·(i mod 2))/2 mod 3.
  const double h = 0.866025404;
  EXPECT_EQ(value_of(PatternKind::hexagon, {0, 0, 0}), 0.0);
  EXPECT_EQ(value_of(PatternKind::hexagon, {0.95, 0, 0}), 0.0);        // corner of the central hexagon on x
  EXPECT_EQ(value_of(PatternKind::hexagon, {0, 0, 2 * h}), 1.0);
  EXPECT_EQ(value_of(PatternKind::hexagon, {0, 0, 4 * h}), 2.0);
  EXPECT_EQ(value_of(PatternKind::hexagon, {0, 0, 6 * h}), 0.0);
  EXPECT_EQ(value_of(PatternKind::hexagon, {1.5, 0, h}), 2.0);
  EXPECT_EQ(value_of(PatternKind::hexagon, {1.5, 0, 3 * h}), 0.0);
  EXPECT_EQ(value_of(PatternKind::hexagon, {-1.5, 0, h}), 2.0);        // mirrored in x
  EXPECT_EQ(value_of(PatternKind::hexagon, {0, 0, -2 * h}), 2.0);      // periodic in z
}

TEST(Pattern, BrickHasMortarAtTheLowSideOfEachBrick) {
  PatternParams b;
  b.kind = PatternKind::brick;
  b.brick_size = {8, 3, 4.5};
  b.mortar = 0.5;
  EXPECT_EQ(pattern_value(b, {4, 1.5, 1}), 1.0);      // inside the first brick
  EXPECT_EQ(pattern_value(b, {4, -0.2, 2}), 0.0);     // bed joint: y + mortar within [0, mortar] of a course
  EXPECT_EQ(pattern_value(b, {-0.2, 1.5, 1}), 0.0);   // head joint of the first course at x = 0
  EXPECT_EQ(pattern_value(b, {-0.2, 4.5, 1}), 1.0);   // the second course is offset by half a brick…
  EXPECT_EQ(pattern_value(b, {3.8, 4.5, 1}), 0.0);    // …so its joint is at x = 4
  EXPECT_EQ(pattern_value(b, {2, 1.5, 2.0}), 0.0);    // facing joint of the first course at z = 2.25 − mortar
  EXPECT_EQ(pattern_value(b, {2, 4.5, -0.2}), 0.0);   // and of the second course at z = 0
}

TEST(Wave, ShapesAndFrequency) {
  WaveParams w;
  EXPECT_DOUBLE_EQ(apply_wave(1.0, w), 1.0);    // fmod by 1.00001 keeps an exact 1
  EXPECT_NEAR(apply_wave(-0.25, w), 0.75, 1e-15);
  w.frequency = 2;
  w.phase = 0.1;
  EXPECT_NEAR(apply_wave(0.3, w), std::fmod(0.7, 1.00001), 1e-15);
  w = WaveParams{};
  w.wave = WaveType::triangle;
  EXPECT_NEAR(apply_wave(0.25, w), 0.5, 1e-15);
  EXPECT_NEAR(apply_wave(0.75, w), 0.5, 1e-15);
  w.wave = WaveType::sine;
  EXPECT_NEAR(apply_wave(0.25, w), 1.0, 1e-12);
  w.wave = WaveType::scallop;
  EXPECT_NEAR(apply_wave(0.5, w), std::sin(std::numbers::pi / 2), 1e-12);
  w.wave = WaveType::cubic;
  EXPECT_NEAR(apply_wave(0.25, w), 0.15625, 1e-15);
  w.wave = WaveType::poly;
  w.exponent = 3;
  EXPECT_NEAR(apply_wave(0.5, w), 0.125, 1e-15);
}

Pigment gradient_pigment(std::vector<MapEntry> map) {
  Pigment p;
  p.pattern = PatternKind::gradient;
  p.entries = std::move(map);
  return p;
}

TEST(ColourMap, InterpolatesAllFiveChannelsBetweenNeighbours) {
  const RenderPigment r = build_render_pigment(
      gradient_pigment({{0.2, {0, 0, 0, 0, 0}, nullptr}, {0.6, {1, 0.5, 0, 0.4, 0.8}, nullptr}}));
  const Colour c = evaluate_pigment(r, {0.5, 0, 0});
  EXPECT_NEAR(c.r, 0.75, 1e-12);
  EXPECT_NEAR(c.g, 0.375, 1e-12);
  EXPECT_NEAR(c.f, 0.3, 1e-12);
  EXPECT_NEAR(c.t, 0.6, 1e-12);
  EXPECT_EQ(evaluate_pigment(r, {0.1, 0, 0}).r, 0.0);   // below the first entry
  EXPECT_EQ(evaluate_pigment(r, {0.9, 0, 0}).r, 1.0);   // above the last
}

TEST(ColourMap, EqualValuesMakeAHardEdge) {
  const RenderPigment r = build_render_pigment(gradient_pigment(
      {{0.5, {1, 0, 0, 0, 0}, nullptr}, {0.5, {0, 0, 1, 0, 0}, nullptr}, {1.0, {0, 0, 0, 0, 0}, nullptr}}));
  EXPECT_EQ(evaluate_pigment(r, {0.5, 0, 0}).r, 1.0);         // the value itself takes the first
  const Colour above = evaluate_pigment(r, {0.5 + 1e-9, 0, 0});   // just above: the second, fading toward black
  EXPECT_EQ(above.r, 0.0);
  EXPECT_NEAR(above.b, 1.0, 1e-8);
}

TEST(ColourMap, DefaultMapIsBlackToWhite) {
  Pigment p;
  p.pattern = PatternKind::gradient;
  EXPECT_NEAR(evaluate_pigment(build_render_pigment(p), {0.3, 0, 0}).g, 0.3, 1e-12);
}

TEST(PigmentMap, ChildPigmentsSeeTheOuterPatternSpace) {
  auto inner = std::make_shared<Pigment>();
  inner->pattern = PatternKind::gradient;   // black→white along x of the *outer* pattern space
  Pigment outer = gradient_pigment({{0.0, {}, inner}, {1.0, {}, inner}});
  outer.world_from_pattern = Matrix::scaling({2, 2, 2});
  // world x = 0.8 → outer pattern x = 0.4 → the inner gradient sees 0.4 too.
  EXPECT_NEAR(evaluate_pigment(build_render_pigment(outer), {0.8, 0, 0}).r, 0.4, 1e-12);
}

// ---- noise: statistics, not POV-Ray's values ----------------------------------------------------------

struct Stats {
  double min = 1e9, max = -1e9, mean = 0, sd = 0;
};
template <class F> Stats sample(F f) {
  constexpr int kCount = 40000;
  Stats s;
  double sum = 0, sum2 = 0;
  for (int i = 0; i < kCount; ++i) {
    // A low-discrepancy walk through a large volume, away from the lattice planes.
    const Vec3 p{std::fmod(i * 0.7548776662, 1.0) * 97.3 - 40, std::fmod(i * 0.5698402910, 1.0) * 83.1 - 31,
                 std::fmod(i * 0.3141592653, 1.0) * 71.7 - 22};
    const double v = f(p);
    s.min = std::min(s.min, v);
    s.max = std::max(s.max, v);
    sum += v;
    sum2 += v * v;
  }
  s.mean = sum / kCount;
  s.sd = std::sqrt(sum2 / kCount - s.mean * s.mean);
  return s;
}

// Values POV-Ray 3.7.0.10 printed for these points (f_noise_generator(x, y, z, g) and vturbulence(2, 0.5, 1, P),
// which is DNoise, through #debug str(…, 0, 17)): povtrace's noise is POV-Ray's, not just alike.
TEST(Noise, MatchesPovRayValuesAtSamplePoints) {
  struct Sample {
    Vec3 p;
    double g1, g2, g3;
    Vec3 d;
  };
  const Sample samples[] = {
      {{0.3, 1.7, -2.2}, 0.52718639941302281, 0.52885147806171373, 0.67029632432102426,
       {0.02718639941302282, 0.32095078329650184, 0.26787703338265589}},
      {{-5.25, 0.125, 3.9}, 0.40779956304798592, 0.47036914143691277, 0.71898011874495094,
       {-0.09220043695201410, -0.08201685601260381, 0.19847181430114144}},
      {{123.456, -78.9, 0.001}, 0.40375002113701491, 0.46838544976348978, 0.78057414611131193,
       {-0.09624997886298507, -0.08513222444496608, 0.32905526927836259}},
      {{-0.5, -0.5, -0.5}, 0.59225963749999999, 0.56072798246486522, 0.34244873489114513,
       {0.09225963750000002, -0.26860660624999999, -0.05210759999999999}}};
  for (const Sample& s : samples) {
    EXPECT_NEAR(noise(s.p, NoiseGenerator::original), s.g1, 1e-15);
    EXPECT_NEAR(noise(s.p, NoiseGenerator::range_corrected), s.g2, 1e-15);
    EXPECT_NEAR(noise(s.p, NoiseGenerator::perlin), s.g3, 1e-15);
    const Vec3 d = vector_noise(s.p);
    EXPECT_NEAR(d.x, s.d.x, 1e-15);
    EXPECT_NEAR(d.y, s.d.y, 1e-15);
    EXPECT_NEAR(d.z, s.d.z, 1e-15);
  }
}

TEST(Noise, RangeCorrectedNoiseIsInZeroOneCentredOnAHalf) {
  const Stats s = sample([](Vec3 p) { return noise(p, NoiseGenerator::range_corrected); });
  EXPECT_GE(s.min, 0.0);
  EXPECT_LE(s.max, 1.0);
  EXPECT_NEAR(s.mean, 0.5, 0.02);
  // POV-Ray documents a raw standard deviation of about 0.257, i.e. 0.126 after its 0.49 stretch.
  EXPECT_GT(s.sd, 0.08);
  EXPECT_LT(s.sd, 0.17);
  EXPECT_LT(s.min, 0.2);   // uses most of the range
  EXPECT_GT(s.max, 0.8);
}

TEST(Noise, OriginalNoiseIsClippedToZeroOne) {
  const Stats s = sample([](Vec3 p) { return noise(p, NoiseGenerator::original); });
  EXPECT_GE(s.min, 0.0);
  EXPECT_LE(s.max, 1.0);
  EXPECT_NEAR(s.mean, 0.5, 0.03);
  EXPECT_GT(s.sd, 0.16);   // about twice the spread of the corrected noise (no 0.49 stretch), then clipped
}

TEST(Noise, IsContinuousAcrossLatticeCells) {
  for (double k : {-3.0, -1.0, 0.0, 1.0, 2.0, 17.0}) {
    const Vec3 below{k - 1e-9, 0.37, 0.61}, above{k + 1e-9, 0.37, 0.61};
    EXPECT_NEAR(noise(below, NoiseGenerator::range_corrected), noise(above, NoiseGenerator::range_corrected), 1e-7);
    const Vec3 dv = vector_noise(below) - vector_noise(above);
    EXPECT_LT(length(dv), 1e-7);
  }
}

TEST(Noise, VariesOnTheScaleOfTheUnitLattice) {
  // Neighbouring points a small step apart differ little; points a few cells apart are uncorrelated.
  double near_sum = 0, far_sum = 0;
  for (int i = 0; i < 2000; ++i) {
    const Vec3 p{i * 0.731, i * 0.417, i * 0.293};
    const double v = noise(p, NoiseGenerator::range_corrected);
    near_sum += std::fabs(v - noise(p + Vec3{0.01, 0, 0}, NoiseGenerator::range_corrected));
    far_sum += std::fabs(v - noise(p + Vec3{3.5, 0, 0}, NoiseGenerator::range_corrected));
  }
  EXPECT_LT(near_sum / 2000, 0.01);
  EXPECT_GT(far_sum / 2000, 0.05);
}

TEST(Turbulence, IsTheOctaveSumWithOmegaAndLambda) {
  const Vec3 p{1.3, -2.7, 0.45};
  Turbulence t;
  t.octaves = 3;
  t.omega = 0.4f;
  t.lambda = 3.0f;
  const double w = 0.4f;   // omega is kept in single precision, as POV-Ray does
  const auto n = [](Vec3 q) { return noise(q, NoiseGenerator::original); };
  EXPECT_NEAR(turbulence(p, t, NoiseGenerator::original), n(p) + w * n(p * 3.0) + w * w * n(p * 9.0), 1e-15);
  const auto c = [](Vec3 q) { return 2.0 * noise(q, NoiseGenerator::range_corrected) - 0.5; };
  EXPECT_NEAR(turbulence(p, t, NoiseGenerator::range_corrected),
              std::clamp(c(p), 0.0, 1.0) + w * c(p * 3.0) + w * w * c(p * 9.0), 1e-15);
  const Vec3 v = vector_turbulence(p, t);
  const Vec3 expected = vector_noise(p) + vector_noise(p * 3.0) * w + vector_noise(p * 9.0) * (w * w);
  EXPECT_LT(length(v - expected), 1e-15);
  t.octaves = 1;
  EXPECT_EQ(turbulence(p, t, NoiseGenerator::original), n(p));
}

TEST(NoisePatterns, MarbleAndWoodWithoutTurbulenceAreGeometric) {
  EXPECT_DOUBLE_EQ(value_of(PatternKind::marble, {0.3, 5, 5}), 0.3);
  EXPECT_DOUBLE_EQ(value_of(PatternKind::wood, {3, 4, 99}), 5.0);
}

TEST(NoisePatterns, ValuesStayInRange) {
  for (PatternKind k : {PatternKind::bozo, PatternKind::granite, PatternKind::agate}) {
    PatternParams params;
    params.kind = k;
    params.turbulence = Turbulence{};
    const Stats s = sample([&](Vec3 p) { return pattern_value(params, p); });
    EXPECT_GE(s.min, 0.0);
    EXPECT_LE(s.max, k == PatternKind::granite ? 2.0 : 1.0);   // granite sums six ridges of weight ½^k
    EXPECT_GT(s.sd, 0.02);
  }
}

// The normal patterns used as pigments (POV-Ray's Evaluate_TPat): bumps is the noise, dents its cube, wrinkles
// ten octaves halved; ripples and waves average sines of the distances to the wave sources.
TEST(NoisePatterns, NormalPatternsAsPigments) {
  PatternParams params;
  const Vec3 q{0.3, 1.7, -2.2};
  params.kind = PatternKind::bumps;
  const double n = pattern_value(params, q);
  EXPECT_EQ(n, noise(q, params.noise_generator));
  params.kind = PatternKind::dents;
  EXPECT_DOUBLE_EQ(pattern_value(params, q), n * n * n);
  params.kind = PatternKind::wrinkles;
  double expected = std::clamp(2 * n - 0.5, 0.0, 1.0), weight = 0.5;
  for (int i = 1; i < 10; ++i, weight /= 2)
    expected += weight * std::clamp(2 * noise(q * std::pow(2.0, i), params.noise_generator) - 0.5, 0.0, 1.0);
  EXPECT_DOUBLE_EQ(pattern_value(params, q), expected / 2);
  const Stats w = sample([&](Vec3 p) { return pattern_value(params, p); });
  EXPECT_GE(w.min, 0.0);
  EXPECT_LE(w.max, 1.0);   // 1 + ½ + … + ½⁹ < 2, halved
  EXPECT_GT(w.sd, 0.02);
  params.kind = PatternKind::ripples;
  const Stats r = sample([&](Vec3 p) { return pattern_value(params, p * 10.0); });
  EXPECT_GE(r.min, 0.0);
  EXPECT_LE(r.max, 1.0);
  EXPECT_NEAR(r.mean, 0.5, 0.1);
  params.kind = PatternKind::waves;
  const Stats v = sample([&](Vec3 p) { return pattern_value(params, p * 10.0); });
  EXPECT_GT(v.sd, 0.01);
  EXPECT_NEAR(v.mean, 0.5, 0.1);   // 0.2·(2.5 + mean of sines / frequency)
}

// warp { repeat x*2 offset <0, 1, 0> flip x }: x = 5.5 lies in slab 2 (even) at 1.5, shifted 2 along y; x = 3.5
// lies in slab 1 (odd) at 1.5, mirrored to −1.5 and moved back into the slab (2 − 1.5), shifted 1 along y.
TEST(Pattern, RepeatWarpMapsEverySlabOntoTheFirst) {
  RenderPigment p;
  PatternStep step;
  step.repeat = RepeatWarp{0, 2.0, {0, 1, 0}, {-1, 1, 1}};
  p.steps.push_back(step);
  const Vec3 even = to_pattern_space(p, {5.5, 0.25, 0.75});
  EXPECT_DOUBLE_EQ(even.x, 1.5);
  EXPECT_DOUBLE_EQ(even.y, 2.25);
  const Vec3 odd = to_pattern_space(p, {3.5, 0.25, 0.75});
  EXPECT_DOUBLE_EQ(odd.x, 0.5);
  EXPECT_DOUBLE_EQ(odd.y, 1.25);
  EXPECT_DOUBLE_EQ(odd.z, 0.75);
  const Vec3 negative = to_pattern_space(p, {-0.5, 0, 0});   // slab −1 is odd too
  EXPECT_DOUBLE_EQ(negative.x, 0.5);
  EXPECT_DOUBLE_EQ(negative.y, -1.0);
}

// The function pattern: the function's value, above 1 wrapped by fmod, below 0 left for the wave step; a value
// that is not a number counts as 0.
TEST(Pattern, FunctionPatternWrapsValuesAboveOne) {
  const SceneDescription scene = parse_scene_text(
      "#version 3.7;\nsphere { 0, 1 pigment { function { x * 3 } } }\nsphere { 0, 1 pigment { function { x / x } } }\n",
      "test.pov", {});
  PatternParams params;
  params.kind = PatternKind::function;
  params.function = scene.objects.at(0).texture->layers.back().pigment.function;
  ASSERT_TRUE(params.function);
  EXPECT_EQ(pattern_value(params, {0.5, 0, 0}), std::fmod(1.5, 1.0));
  EXPECT_EQ(pattern_value(params, {0.2, 0, 0}), 0.2 * 3);
  EXPECT_EQ(pattern_value(params, {-0.5, 0, 0}), -1.5);
  EXPECT_EQ(pattern_value(params, {1.0 / 3.0, 0, 0}), (1.0 / 3.0) * 3);   // exactly 1 stays 1
  params.function = scene.objects.at(1).texture->layers.back().pigment.function;
  EXPECT_EQ(pattern_value(params, {0, 0, 0}), 0.0);
  EXPECT_EQ(pattern_value(params, {2, 0, 0}), 1.0);
}

}  // namespace
}  // namespace povtrace::render

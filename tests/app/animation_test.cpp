// Animation (issue 18): the frames, clocks, declared values and file names povtrace derives from the animation
// options, against what Debian's povray 3.7.0.10 did with the same switches. The expected lines below are the
// output of `povray -D +W8 +H6 vals.pov <switches>` for the scene kValuesScene (its #debug line per frame), and the
// file names are those povray wrote (`ls` after the run).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "app/animation.hpp"
#include "app/options.hpp"
#include "parser/parse_scene.hpp"
#include "scene/source.hpp"

namespace povtrace::app {
namespace {

constexpr const char* kValuesScene =
    R"(#debug concat("F ", str(frame_number,0,0), " clock=", str(clock,0,9), " on=", str(clock_on,0,0), )"
    R"(" delta=", str(clock_delta,0,9), " if=", str(initial_frame,0,0), " ff=", str(final_frame,0,0), )"
    R"(" ic=", str(initial_clock,0,6), " fc=", str(final_clock,0,6), "\n")
camera { location <0,0,-3> look_at 0 }
)";

// The options povray's switches set: +KFI +KFF +KI +KF +KC +SF +EF +STP +K (the option parser's own tests check
// the switches; here they are written out so that these tests check the arithmetic alone).
struct Switches {
  std::optional<int> kfi{}, kff{};
  std::optional<double> ki{}, kf{};
  bool kc = false;
  std::optional<double> sf{}, ef{};
  int stp = 1;
  std::optional<double> k{};
};

AnimationOptions animation(const Switches& s) {
  AnimationOptions a;
  a.initial_frame = s.kfi;
  a.final_frame = s.kff;
  a.initial_clock = s.ki;
  a.final_clock = s.kf;
  a.cyclic = s.kc;
  a.subset_start = s.sf;
  a.subset_end = s.ef;
  a.frame_step = s.stp;
  a.clock = s.k;
  return a;
}

// Every frame's #debug line, as povtrace's parser prints it for the plan of `switches`.
std::vector<std::string> debug_lines(const Switches& switches) {
  const FramePlan plan = plan_frames(animation(switches));
  std::vector<std::string> lines;
  for (long long i = 0; i < plan.count(); ++i) {
    ParseOptions parse;
    set_frame_values(plan, plan.at(i), parse);
    std::string text;
    parse.message_sink = [&](const std::string& m) { text += m; };
    parse_scene_text(kValuesScene, "vals.pov", parse);
    while (!text.empty() && text.back() == '\n') text.pop_back();
    lines.push_back(text);
  }
  return lines;
}

std::vector<std::string> file_names(const Switches& switches) {
  const FramePlan plan = plan_frames(animation(switches));
  std::vector<std::string> names;
  for (long long i = 0; i < plan.count(); ++i)
    names.push_back(frame_output_path("vals.png", plan, plan.at(i).number).string());
  return names;
}

struct PovrayRun {
  Switches switches;
  std::vector<std::string> lines;   // povray's #debug output, one line per frame
  std::vector<std::string> files;   // the files povray wrote
};

class MatchesPovray : public ::testing::TestWithParam<PovrayRun> {};

TEST_P(MatchesPovray, DeclaredValuesAndFileNames) {
  EXPECT_EQ(debug_lines(GetParam().switches), GetParam().lines);
  EXPECT_EQ(file_names(GetParam().switches), GetParam().files);
}

INSTANTIATE_TEST_SUITE_P(Switches, MatchesPovray, ::testing::Values(
    PovrayRun{Switches{}, {"F 0 clock=0.000000000 on=0 delta=0.000000000 if=0 ff=0 ic=0.000000 fc=0.000000"}, {"vals.png"}},
    PovrayRun{Switches{.k = 0.5}, {"F 0 clock=0.500000000 on=1 delta=0.000000000 if=0 ff=0 ic=0.000000 fc=0.000000"},
              {"vals.png"}},
    // Initial and final frame both 0 (or both 1) is a still, whose clock is +K's.
    PovrayRun{Switches{.kfi = 0, .kff = 0, .k = 0.25},
              {"F 0 clock=0.250000000 on=1 delta=0.000000000 if=0 ff=0 ic=0.000000 fc=0.000000"}, {"vals.png"}},
    // Cyclic: the final frame becomes 31 (declared, and two digits); the subset ends at the user's 30.
    PovrayRun{Switches{.kfi = 1, .kff = 30, .kc = true, .sf = 28},
              {"F 28 clock=0.899999976 on=1 delta=0.033333300 if=1 ff=31 ic=0.000000 fc=1.000000",
               "F 29 clock=0.933333337 on=1 delta=0.033333300 if=1 ff=31 ic=0.000000 fc=1.000000",
               "F 30 clock=0.966666639 on=1 delta=0.033333300 if=1 ff=31 ic=0.000000 fc=1.000000"},
              {"vals28.png", "vals29.png", "vals30.png"}},
    PovrayRun{Switches{.kfi = 1, .kff = 5, .ki = 0.3, .kf = 0.7, .stp = 2},
              {"F 1 clock=0.300000012 on=1 delta=0.100000000 if=1 ff=5 ic=0.300000 fc=0.700000",
               "F 3 clock=0.500000000 on=1 delta=0.100000000 if=1 ff=5 ic=0.300000 fc=0.700000",
               "F 5 clock=0.699999988 on=1 delta=0.100000000 if=1 ff=5 ic=0.300000 fc=0.700000"},
              {"vals1.png", "vals3.png", "vals5.png"}},
    PovrayRun{Switches{.kfi = 1, .kff = 30, .kf = 0.1, .sf = 3, .ef = 3},
              {"F 3 clock=0.006896552 on=1 delta=0.003448280 if=1 ff=30 ic=0.000000 fc=0.100000"}, {"vals03.png"}}));

TEST(FramePlan, FractionalSubsetsCountFramesFromTheInitialOne) {
  // povray +KFF10 +SF0.5 +EF0.8 wrote vals05.png … vals08.png.
  EXPECT_EQ(file_names(Switches{.kff = 10, .sf = 0.5, .ef = 0.8}),
            (std::vector<std::string>{"vals05.png", "vals06.png", "vals07.png", "vals08.png"}));
}

TEST(FramePlan, ANumberWiderThanTheDigitsOverwritesTheStem) {
  // povray +KFF12 +SF148 +EF150 wrote val148.png, val149.png, val150.png.
  EXPECT_EQ(file_names(Switches{.kff = 12, .sf = 148, .ef = 150}),
            (std::vector<std::string>{"val148.png", "val149.png", "val150.png"}));
}

TEST(FramePlan, SingleFrameAnimationHasAFiniteClock) {
  // povray +KFI2 +KFF2 divides by zero (its clock is nan, clock_delta inf); povtrace keeps Initial_Clock.
  const FramePlan plan = plan_frames(animation(Switches{.kfi = 2, .kff = 2}));
  ASSERT_EQ(plan.count(), 1);
  EXPECT_EQ(plan.at(0).number, 2);
  EXPECT_EQ(plan.at(0).clock, 0.0);
  EXPECT_EQ(frame_output_path("vals.png", plan, 2).string(), "vals2.png");
}

TEST(FramePlan, DigitsFollowTheFinalFrame) {
  EXPECT_EQ(plan_frames(animation(Switches{.kff = 9})).digits, 1);
  EXPECT_EQ(plan_frames(animation(Switches{.kff = 10})).digits, 2);
  EXPECT_EQ(plan_frames(animation(Switches{.kff = 99})).digits, 2);
  EXPECT_EQ(plan_frames(animation(Switches{.kff = 99, .kc = true})).digits, 3);   // cyclic: 100
  EXPECT_EQ(plan_frames(animation(Switches{.kff = 100})).digits, 3);
}

TEST(FramePlan, HugeFrameCountsCostNoMemory) {
  const FramePlan plan = plan_frames(animation(Switches{.kff = 2000000000}));
  EXPECT_EQ(plan.count(), 2000000000);
  EXPECT_EQ(plan.at(plan.count() - 1).number, 2000000000);
  EXPECT_EQ(plan.digits, 10);
}

TEST(FramePlan, FoldersAndExtensionsOfTheStillPathAreKept) {
  const FramePlan plan = plan_frames(animation(Switches{.kff = 12}));
  EXPECT_EQ(frame_output_path("renders/out.exr", plan, 7).string(), "renders/out07.exr");
}

TEST(DeclaredValue, SixSignificantDigitsAsPovrayReadsThem) {
  // povray Declare=N=1234567 Declare=M=0.1: N=1234570.000000, M=0.100000000000 (not the float nearest 0.1).
  EXPECT_EQ(declared_value(1234567), 1234570.0);
  EXPECT_EQ(declared_value(0.1), 0.1);
  EXPECT_EQ(declared_value(1.0 / 30.0), 0.0333333);
}

}  // namespace
}  // namespace povtrace::app

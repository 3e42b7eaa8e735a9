// The frames an animation renders and the values each frame's parse sees, from the options as written
// (AnimationOptions), following POV-Ray 3.7's front end: vfe.cpp decides whether the render is animated at all,
// animationprocessing.cpp computes the frame range, the subset, the clock and the digits of the file numbers, and
// imageprocessing.cpp numbers the output files. Pure functions: no file is touched here.
#pragma once

#include <filesystem>
#include <vector>

#include "app/options.hpp"
#include "parser/parse_scene.hpp"

namespace povtrace::app {

struct Frame {
  long long number = 0;                // frame_number (0 for a still)
  std::optional<double> clock;         // the parse's `clock` (nullopt: clock_on is false and clock is 0)
};

// Frames are computed on demand (`at`), so that Final_Frame=1000000000 costs no memory.
struct FramePlan {
  bool animated = false;               // false: one render, output not numbered, the six values declared 0
  std::optional<double> still_clock;   // +K's clock when not animated
  long long first = 0, last = 0;       // the subset's first and last frame rendered
  int step = 1;                        // Frame_Step
  long long initial_frame = 0;         // after the clamps (the clock's origin)
  double clock_delta = 0;              // in double, as POV-Ray computes the clocks
  int digits = 0;                      // width of the frame number in file names (0 when not animated)
  ParseOptions::FrameValues declared;  // the values every frame shares (frame_number is set per frame)

  long long count() const;             // frames to render
  Frame at(long long index) const;     // the index-th frame, in render order
};

FramePlan plan_frames(const AnimationOptions& animation);

// A value as POV-Ray's parser receives a declared number (Declare=, frame_number, clock_delta …): rounded to a
// float, printed with six significant digits and read back (backend scene.cpp), so Declare=N=1234567 is 1234570.
double declared_value(double value);

// The parse's animation inputs for one frame of the plan.
void set_frame_values(const FramePlan& plan, const Frame& frame, ParseOptions& parse);

// The file a frame is written to: `still` is the output path of a single render (resolved_output_path); an
// animation's frame number, zero-padded to `digits`, goes between its stem and its extension (out.png →
// out07.png). As in POV-Ray, a number wider than `digits` (a subset end past the final frame) overwrites the
// stem's last characters.
std::filesystem::path frame_output_path(const std::filesystem::path& still, const FramePlan& plan,
                                        long long frame_number);

}  // namespace povtrace::app

// POV-Ray 3.7's animation arithmetic, reproduced for identical clocks and file names (sources in animation.hpp).
// POV-Ray passes the clock from its front end to its parser as a single-precision float (POVMSFloat), so the
// clock is rounded to float here: `clock` of frame 28 of a cyclic 1…30 is 0.899999976, as POV-Ray's #debug shows.
// The six declared values go as floats too, and are then printed with six significant digits and parsed again
// (scene.cpp, like every Declare=): declared_value reproduces that, so clock_delta of 0…1 over 1…31 is 0.0333333.
#include "app/animation.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace povtrace::app {
namespace {

double as_float(double value) { return static_cast<double>(static_cast<float>(value)); }
double as_declared(double value) { return declared_value(value); }

// Subset_Start_Frame / Subset_End_Frame: 0 or at least 1 is a frame number, a value in (0,1) a fraction of the
// frame count; both truncate toward zero, as POV-Ray's float-to-int conversions do. Values are bounded first so
// that a huge one cannot overflow the conversion.
long long subset_frame(double written, long long frame_count) {
  const float value = static_cast<float>(std::clamp(written, 0.0, 2e9));
  if (value == 0.0f || value >= 1.0f) return static_cast<long long>(value);
  return static_cast<long long>(static_cast<float>(frame_count) * value);
}

int digit_count(long long n) {
  int digits = 1;
  for (; n >= 10; n /= 10) ++digits;
  return digits;
}

}  // namespace

double declared_value(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", static_cast<double>(static_cast<float>(value)));
  return std::strtod(text, nullptr);
}

long long FramePlan::count() const { return animated ? (last - first) / step + 1 : 1; }

Frame FramePlan::at(long long index) const {
  if (!animated) return Frame{0, still_clock};
  const long long number = first + index * step;
  // POV-Ray: clock = initial_clock + clock_delta × (frame − initial_frame), in double, then stored as a float.
  const double clock = clock_delta * static_cast<double>(number - initial_frame) + declared.initial_clock;
  return Frame{number, as_float(clock)};
}

FramePlan plan_frames(const AnimationOptions& a) {
  FramePlan plan;
  plan.still_clock = a.clock;
  // vfe.cpp: a render is a still when Initial_Frame and Final_Frame (unset counting as 0 here) are both 0 or
  // both 1; its six values are declared 0 and its clock is +K's, if any.
  const int written_initial = a.initial_frame.value_or(0), written_final = a.final_frame.value_or(0);
  if ((written_initial == 0 && written_final == 0) || (written_initial == 1 && written_final == 1)) return plan;

  plan.animated = true;
  // animationprocessing.cpp: defaults 1, 1, 0.0, 1.0 and 1, then the clamps; Cyclic_Animation adds a frame
  // first, so the last frame rendered stops one clock step short of Final_Clock.
  const long long initial = std::max(a.initial_frame.value_or(1), 0);
  long long final = std::max<long long>(a.final_frame.value_or(1), initial);
  const float initial_clock = static_cast<float>(a.initial_clock.value_or(0.0));
  const float final_clock = static_cast<float>(a.final_clock.value_or(1.0));
  plan.step = std::max(a.frame_step, 1);
  if (a.cyclic) ++final;

  const long long frame_count = final - initial + 1;
  plan.first = a.subset_start ? std::max(subset_frame(*a.subset_start, frame_count), initial) : initial;
  plan.last = a.subset_end ? std::max(subset_frame(*a.subset_end, frame_count), plan.first)
                           : final - (a.cyclic ? 1 : 0);
  plan.last = std::max(plan.last, plan.first);   // without +EF, a subset start past the end renders that one frame
  plan.last = plan.first + (plan.last - plan.first) / plan.step * plan.step;

  // One frame (Initial_Frame = Final_Frame, say 2 and 2) has no clock step: POV-Ray divides by zero and its clock
  // is not a number; povtrace keeps the step 0 so the frame's clock is Initial_Clock.
  plan.clock_delta = final == initial ? 0.0
                                      : static_cast<double>(final_clock - initial_clock) / static_cast<double>(final - initial);
  plan.initial_frame = initial;
  plan.digits = digit_count(final);
  plan.declared.clock_delta = as_declared(plan.clock_delta);
  plan.declared.final_clock = as_declared(final_clock);
  plan.declared.final_frame = as_declared(static_cast<double>(final));
  plan.declared.initial_clock = as_declared(initial_clock);
  plan.declared.initial_frame = as_declared(static_cast<double>(initial));
  return plan;
}

void set_frame_values(const FramePlan& plan, const Frame& frame, ParseOptions& parse) {
  parse.clock = frame.clock;
  parse.frame = plan.declared;
  if (plan.animated) parse.frame.frame_number = as_declared(static_cast<double>(frame.number));
}

std::filesystem::path frame_output_path(const std::filesystem::path& still, const FramePlan& plan,
                                        long long frame_number) {
  if (!plan.animated) return still;
  std::string name = still.stem().string();
  name.append(static_cast<std::size_t>(plan.digits), '0');
  for (std::size_t i = name.size(); frame_number > 0 && i > 0; frame_number /= 10) name[--i] = static_cast<char>('0' + frame_number % 10);
  return still.parent_path() / (name + still.extension().string());
}

}  // namespace povtrace::app

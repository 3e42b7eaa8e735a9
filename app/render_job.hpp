// One render from options to file, with timing, progress, summary and --stats JSON; and the --vs-povray
// cross-check. Split from main() so tests can run a whole job in-process.
#pragma once

#include <atomic>
#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "app/animation.hpp"
#include "app/messages.hpp"
#include "app/options.hpp"
#include "parser/parse_scene.hpp"
#include "renderer/image/image.hpp"
#include "renderer/render.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::app {

struct RenderTimes {
  double parse_s = 0, build_s = 0, render_s = 0, write_s = 0, total_s = 0;
};

struct JobResult {
  int exit_status = 0;
  image::Image image;                 // the linear framebuffer that was written
  RenderTimes times;
  render::RayCounts rays;
  std::filesystem::path output;
  long long frames = 0;               // frames rendered (1 for a still)
  bool skipped = false;               // +C: the frame's output file existed, nothing was rendered or written
  // What in the scene POV-Ray draws at random (so its own runs differ): jittered area lights, radiosity.
  std::vector<std::string> random_in_povray;
};

// Parses, builds, renders and writes per `options`: one image, or every frame of an animation (one file each,
// numbered as POV-Ray numbers them, the scene parsed anew per frame). Throws ParseError / ImageError; returns
// exit status 1 when interrupted (the frame being rendered is not written; frames already finished stay).
// The result is the last frame's. Text goes to `messages` (main's, with the +G streams); without them, to a
// Messages opened from options.streams. Runs Pre_/Post_Scene_Command around the job and Pre_/Post_Frame_Command
// around each frame (app/shellouts.hpp). Input "-" reads the scene from standard input.
JobResult run_render(const RenderOptions& options, const std::atomic<bool>& interrupted,
                     Messages* messages = nullptr);

// One frame of `plan` (the whole job for a still): render_frame_pixels, then finish_job with the frame's name.
JobResult render_frame(const RenderOptions& options, const FramePlan& plan, const Frame& frame,
                       const std::atomic<bool>& interrupted, Messages& messages);

// Parses the scene for `frame`, builds and renders it: r.image holds the pixels (nothing is written), r.times
// the parse, build and render seconds; exit_status 1 when interrupted (r.image then empty).
JobResult render_frame_pixels(const RenderOptions& options, const FramePlan& plan, const Frame& frame,
                              const std::atomic<bool>& interrupted, Messages& messages);

// The pieces of run_render that the MPI path (app/mpi_render.cpp) shares, so its ranks parse, render and write
// exactly as one process does: the parser's and the renderer's settings from the options (the region is set by
// the caller), and the end of a job: writes `image` to `output` (the frame's file name; standard output for
// +O-) per the options (atomically), fills r's output and times, prints the summary and the --stats file.
ParseOptions parse_options_from(const RenderOptions& options);
render::RenderSettings render_settings_from(const RenderOptions& options);
void finish_job(const RenderOptions& options, image::Image image, JobResult& r,
                std::chrono::steady_clock::time_point start, const std::filesystem::path& output,
                Messages& messages);

// Renders with povtrace and with `povray` (same options, EXR), prints both times and the comparison, and writes
// `<stem>_vs_povray.png` (povtrace | POV-Ray | heat map). Exit 0 within the image thresholds, 1 outside.
int run_vs_povray(const RenderOptions& options, const std::atomic<bool>& interrupted);

// The --stats JSON text for a finished job.
std::string stats_json(const RenderOptions& options, const JobResult& job);

}  // namespace povtrace::app

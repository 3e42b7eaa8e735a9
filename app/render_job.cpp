#include "app/render_job.hpp"
#include "renderer/photons/photon_map.hpp"

#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <tuple>
#include <sstream>

#include "app/shellouts.hpp"
#include "app/region.hpp"
#include "app/render_state.hpp"
#include "parser/parse_scene.hpp"
#include "renderer/image/compare.hpp"
#include "renderer/object_geometry.hpp"
#include "renderer/pattern_evaluator.hpp"
#include "renderer/render.hpp"
#include "renderer/render_scene.hpp"
#include "scene/source.hpp"

namespace povtrace::app {

namespace {
// Lights with `jitter` anywhere in the scene (top level, in CSG and light groups).
template <class Objects>   // the scene's deque or a CSG's vector
bool has_jittered_area_light(const std::vector<Light>& lights, const Objects& objects) {
  for (const Light& l : lights) {
    if (l.area && l.jitter) return true;
  }
  for (const Object& o : objects) {
    if (const auto* csg = std::get_if<Csg>(&o.shape); csg && has_jittered_area_light(csg->lights, csg->children)) {
      return true;
    }
  }
  return false;
}

// The features of a scene whose samples POV-Ray draws at random, so that two POV-Ray renders differ (named in
// --vs-povray's verdict): area lights with `jitter` (POV-Ray's own generator), and radiosity (its cache depends on
// the order in which its threads finish).
std::vector<std::string> povray_random_features(const SceneDescription& d) {
  std::vector<std::string> found;
  if (has_jittered_area_light(d.lights, d.objects)) found.emplace_back("area lights with jitter");
  if (d.radiosity) found.emplace_back("radiosity (with more than one thread)");
  return found;
}
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }
}  // namespace

ParseOptions parse_options_from(const RenderOptions& o) {
  ParseOptions p;
  p.library_paths = o.library_paths;
  // POV-Ray's parser reads each Declare= as printed with six significant digits (animation.hpp, declared_value).
  for (const auto& [name, value] : o.declares) p.declares.emplace_back(name, declared_value(value));
  p.string_declares = o.string_declares;
  p.include_header = o.include_header;
  if (o.language_version) p.initial_language_version = static_cast<int>(std::lround(*o.language_version * 100.0));
  p.warning_level = o.warning_level;
  p.image_width = o.width;
  p.image_height = o.height;
  p.output_alpha = o.output_alpha;
  p.object_geometry = std::make_shared<render::RendererGeometry>();
  p.pattern_evaluator = std::make_shared<render::RendererPatterns>();
  p.povray_tolerances = o.povray_tolerances;
  p.expression_programs = o.expression_programs;
  return p;
}

render::RenderSettings render_settings_from(const RenderOptions& o) {
  render::RenderSettings s;
  s.width = o.width;
  s.height = o.height;
  s.threads = o.threads;
  s.antialias = o.antialias;
  s.antialias_threshold = o.antialias_threshold;
  s.antialias_depth = o.antialias_depth;
  s.sampling_method = o.sampling_method;
  s.jitter = o.jitter;
  s.jitter_amount = o.jitter_amount;
  s.antialias_gamma = o.antialias_gamma;
  s.output_alpha = o.output_alpha;
  s.shading = o.lighting == LightingModel::textbook ? render::ShadingModel::textbook : render::ShadingModel::povray;
  s.quality = o.quality;
  s.radiosity_povray_order = o.radiosity_povray_order;
  return s;
}

namespace {

// A progress line for renders that take over a second (percent, elapsed, ETA): rewritten in place on a
// terminal, a line per quarter otherwise (logs stay short). `saved` is the share of the blocks a +C render takes
// from its state file (done from the start, so not counted in the rate the ETA assumes).
std::function<void(double)> progress_reporter(Clock::time_point start, Messages& messages, double saved = 0.0) {
  const bool tty = isatty(STDERR_FILENO) != 0;
  if (!messages.console(Stream::render)) return [](double) {};
  auto last_quarter = std::make_shared<int>(0);
  return [=](double done) {
    const double elapsed = seconds_since(start);
    if (elapsed < 1.0 || done <= saved) return;
    const double eta = elapsed * (1.0 - done) / (done - saved);
    char line[128];
    std::snprintf(line, sizeof line, "povtrace: rendering %3.0f%%, %.1f s elapsed, ETA %.1f s", done * 100, elapsed, eta);
    if (tty) {
      std::cerr << "\r" << line << std::flush;
    } else if (static_cast<int>(done * 4) > *last_quarter) {
      *last_quarter = static_cast<int>(done * 4);
      std::cerr << line << "\n";
    }
  };
}

void print_summary(const RenderOptions& o, const JobResult& r, Messages& messages) {
  char line[1024];
  std::snprintf(line, sizeof line,
               "povtrace: %dx%d, rays: %llu camera, %llu shadow, %llu secondary; parse %.3f s, build %.3f s, "
               "render %.3f s, total %.3f s%s%s\n",
               o.width, o.height, static_cast<unsigned long long>(r.rays.camera),
               static_cast<unsigned long long>(r.rays.shadow), static_cast<unsigned long long>(r.rays.secondary),
               r.times.parse_s, r.times.build_s, r.times.render_s, r.times.total_s,
               r.output.empty() ? "" : " -> ", r.output.string().c_str());
  messages.write(Stream::statistics, line);
}

// The scene's text: the file, or standard input for "-" (+I-). Standard input's text is kept in `stdin_text`
// (the state file's digest needs it; it cannot be read twice).
SceneDescription parse_input(const RenderOptions& options, const ParseOptions& parse_options,
                             std::string& stdin_text) {
  if (options.input != "-") return parse_scene(options.input, parse_options);
  std::ostringstream text;
  text << std::cin.rdbuf();
  stdin_text = text.str();
  return parse_scene_text(stdin_text, "<stdin>", parse_options);
}

bool output_to_stdout(const RenderOptions& options) {
  return options.output && (*options.output == image::standard_output_path || *options.output == "stdout");
}

// A file that exists and is not empty: POV-Ray's test for "this frame was rendered" under +C.
bool rendered_already(const std::filesystem::path& output) {
  std::error_code ec;
  const auto size = std::filesystem::file_size(output, ec);
  return !ec && size > 0;
}

// The render state of one frame (+C, app/render_state.hpp): what was saved by an interrupted render, and the file
// the blocks of this render go to.
struct FrameState {
  std::filesystem::path path;
  std::string settings;
  SavedState saved;
  std::set<std::tuple<int, int, int, int>> saved_blocks;
  std::unique_ptr<StateWriter> writer;
};
}  // namespace

std::string stats_json(const RenderOptions& o, const JobResult& r) {
  std::ostringstream j;
  j.precision(9);
  const auto total_rays = r.rays.camera + r.rays.shadow + r.rays.secondary;
  j << "{\n  \"scene\": \"" << o.input.string() << "\",\n  \"width\": " << o.width << ",\n  \"height\": " << o.height
    << ",\n  \"parse_s\": " << r.times.parse_s << ",\n  \"build_s\": " << r.times.build_s
    << ",\n  \"render_s\": " << r.times.render_s << ",\n  \"write_s\": " << r.times.write_s
    << ",\n  \"total_s\": " << r.times.total_s << ",\n  \"rays\": " << total_rays
    << ",\n  \"camera_rays\": " << r.rays.camera << ",\n  \"shadow_rays\": " << r.rays.shadow
    << ",\n  \"secondary_rays\": " << r.rays.secondary << "\n}\n";
  return j.str();
}

namespace {
// The % codes' values for one frame of the job.
ShellContext frame_context(const RenderOptions& options, const std::string& output, const Frame& frame) {
  ShellContext c = ShellOuts::context_for(options, output);
  c.frame = static_cast<int>(frame.number);
  c.clock = frame.clock.value_or(0.0);
  return c;
}

// What a shell-out's action means for the job, as POV-Ray's *_Return actions: a fatal error throws, an abort
// or quit ends the job (exit 1 for the abort), a skip is left to the caller.
bool ends_job(ShellAction action, const char* key, JobResult& r) {
  if (action == ShellAction::fatal_error) throw std::runtime_error(std::string(key) + " failed (its *_Return is f)");
  if (action == ShellAction::user_abort) r.exit_status = 1;
  return action == ShellAction::user_abort || action == ShellAction::quit || action == ShellAction::skip_all;
}
}  // namespace

JobResult run_render(const RenderOptions& options, const std::atomic<bool>& interrupted, Messages* messages_in) {
  std::optional<Messages> own_messages;
  if (messages_in == nullptr) own_messages.emplace(options.streams);
  Messages& messages = messages_in != nullptr ? *messages_in : *own_messages;
  JobResult r;
  if (options.continue_trace && options.write_file && output_to_stdout(options)) {
    // POV-Ray refuses this too ("Cannot continue trace if output to STDOUT or STDERR is specified").
    throw UsageError("+C (Continue_Trace) cannot continue a render written to standard output (+O-)");
  }
  ShellOuts shellouts(options, [&](const std::string& w) { messages.write(Stream::warning, "povtrace: warning: " + w); });
  const std::string planned_output = options.write_file ? resolved_output_path(options).string() : std::string();
  const ShellAction before = shellouts.run(ShellEvent::pre_scene, ShellOuts::context_for(options, planned_output));
  if (before == ShellAction::fatal_error) throw std::runtime_error("Pre_Scene_Command failed (Pre_Scene_Return=f)");
  if (before != ShellAction::proceed) {
    messages.write(Stream::render, "povtrace: Pre_Scene_Command asked to stop; nothing rendered");
    r.exit_status = before == ShellAction::user_abort ? 1 : 0;
    return r;
  }
  // POV-Ray parses the scene anew for every frame (its #fopen files, rand streams and #declares start over).
  const FramePlan plan = plan_frames(options.animation);
  long long rendered = 0;
  for (long long i = 0; i < plan.count(); ++i) {
    const Frame frame = plan.at(i);
    const std::string frame_output =
        options.write_file ? frame_output_path(resolved_output_path(options), plan, frame.number).string() : "";
    const ShellAction pre = shellouts.run(ShellEvent::pre_frame, frame_context(options, frame_output, frame));
    if (ends_job(pre, "Pre_Frame_Command", r)) break;
    if (pre == ShellAction::skip_frame) continue;
    if (plan.animated) {
      std::ostringstream note;
      note << "povtrace: frame " << frame.number << " (" << i + 1 << " of " << plan.count() << "), clock "
           << frame.clock.value_or(0.0);
      messages.write(Stream::render, note.str());
    }
    r = render_frame(options, plan, frame, interrupted, messages);
    if (r.skipped) {   // +C and the frame's file exists: POV-Ray runs no Post_Frame_Command for it either
      r.frames = rendered;
      continue;
    }
    r.frames = ++rendered;
    if (r.exit_status != 0) return r;
    const ShellAction post = shellouts.run(ShellEvent::post_frame, frame_context(options, r.output.string(), frame));
    if (ends_job(post, "Post_Frame_Command", r)) break;
  }
  if (r.exit_status != 0) return r;
  const ShellAction after = shellouts.run(ShellEvent::post_scene, ShellOuts::context_for(options, r.output.string()));
  if (after == ShellAction::fatal_error) throw std::runtime_error("Post_Scene_Command failed (Post_Scene_Return=f)");
  if (after == ShellAction::user_abort) r.exit_status = 1;
  return r;
}

namespace {
// One frame, parsed, built and rendered; with `write`, kept in a render state file while it renders (+C) and
// written to its numbered file; without, the pixels are returned in r.image (an MPI worker's frame).
JobResult render_one_frame(const RenderOptions& options, const FramePlan& plan, const Frame& frame,
                           const std::atomic<bool>& interrupted, Messages& messages, bool write) {
  JobResult r;
  const auto start = Clock::now();
  const std::optional<image::PixelRect> region = resolve_region(options.region, options.width, options.height);
  ParseOptions parse_options = parse_options_from(options);
  set_frame_values(plan, frame, parse_options);
  parse_options.cancel = &interrupted;   // Ctrl-C during a long (or endless) parse
  DebugLines debug_lines(messages);   // this parse's #debug text: complete lines only, as POV-Ray
  parse_options.classified_sink = [&](ParseOptions::MessageKind kind, const std::string& text) {
    if (kind == ParseOptions::MessageKind::debug) debug_lines.add(text);
    else messages.write(Stream::warning, text);
  };
  std::string stdin_text;
  const SceneDescription description = parse_input(options, parse_options, stdin_text);
  r.times.parse_s = seconds_since(start);

  const std::filesystem::path output = frame_output_path(resolved_output_path(options), plan, frame.number);
  render::RenderSettings settings = render_settings_from(options);
  settings.region = region;
  // Every render to a file keeps a state file of its finished blocks (as POV-Ray's .pov-state), so that +C can
  // continue it after an interrupt; +C first looks for one (after the parse, as POV-Ray).
  std::optional<FrameState> state;
  if (write && options.write_file && !output_to_stdout(options)) {
    state.emplace();
    state->path = state_file_path(output);
    state->settings = state_settings(options, frame, region, settings.block_size,
                                     options.input == "-" ? stdin_text : read_text_file(options.input),
                                     description.file_names ? description.file_names->all()
                                                            : std::vector<std::string>{});
    if (options.continue_trace) {
      state->saved = read_state(state->path, state->settings, options.width, options.height);
      using Status = SavedState::Status;
      if (state->saved.status == Status::other_settings) {
        throw UsageError("+C: the render state file '" + state->path.string() + "' is from a render with other " +
                         "settings (" + state->saved.difference + "); render without +C to start over");
      }
      if (state->saved.status == Status::unreadable) {
        messages.write(Stream::warning, "povtrace: warning: '" + state->path.string() +
                                            "' is not a povtrace render state file (or is damaged); not used");
      }
      if (state->saved.status != Status::usable && rendered_already(output)) {
        // POV-Ray: "File already rendered and continue requested; skipping."
        messages.write(Stream::render, "povtrace: '" + output.string() + "' is already rendered and +C is given; skipped");
        r.skipped = true;
        r.output = output;
        return r;
      }
      if (state->saved.status == Status::usable) {
        for (const image::PixelRect& b : state->saved.blocks) state->saved_blocks.emplace(b.x0, b.y0, b.x1, b.y1);
        std::ostringstream note;
        note << "povtrace: continuing from '" << state->path.string() << "': " << state->saved.blocks.size()
             << " block" << (state->saved.blocks.size() == 1 ? "" : "s") << " already rendered";
        messages.write(Stream::render, note.str());
      } else if (state->saved.status == Status::absent) {
        messages.write(Stream::render, "povtrace: no render state file '" + state->path.string() +
                                           "' to continue from; rendering from the start");
      }
    }
  }

  r.random_in_povray = povray_random_features(description);
  const auto build_start = Clock::now();
  const render::RenderScene scene = render::build_render_scene(
      description, {options.output_alpha, options.povray_tolerances, options.specialise,
                    render::Quality::quick_colours_at(options.quality), options.quality, options.threads});
  r.times.build_s = seconds_since(build_start);
  if (scene.scale != 1.0 && options.verbose) {
    std::ostringstream note;
    note << "povtrace: the scene is rendered rescaled by " << scene.scale
         << " (its size is far from POV-Ray's tolerances; --povray-tolerances keeps it as written)";
    messages.write(Stream::render, note.str());
  }
  for (const auto& w : scene.warnings) messages.write(Stream::warning, "povtrace: warning: " + w);
  if (scene.photons) {   // as POV-Ray's "Surface photons stored" statistic
    std::ostringstream stats;
    stats << "povtrace: photons: " << scene.photons->size() << " stored, gather radius " << scene.photons->gather_radius()
          << "\n";
    messages.write(Stream::statistics, stats.str());
  }

  if (state) {
    state->writer = std::make_unique<StateWriter>(
        state->path, state->settings,
        state->saved.status == SavedState::Status::usable ? std::optional(state->saved.valid_bytes) : std::nullopt);
    StateWriter& writer = *state->writer;
    settings.block_done = [&writer](const image::Image& image, const image::PixelRect& block) {
      writer.record(image, block);
    };
    if (!state->saved_blocks.empty()) {
      const auto& saved = state->saved_blocks;
      settings.skip_block = [&saved](const image::PixelRect& b) { return saved.contains({b.x0, b.y0, b.x1, b.y1}); };
    }
  }

  const auto render_start = Clock::now();
  double saved_share = 0.0;
  if (state && !state->saved.blocks.empty()) {   // the blocks of the grid that meet the rendered area
    const int bs = std::max(4, settings.block_size);
    const image::PixelRect area = region.value_or(image::PixelRect{0, 0, options.width - 1, options.height - 1});
    const double blocks = static_cast<double>(area.x1 / bs - area.x0 / bs + 1) * (area.y1 / bs - area.y0 / bs + 1);
    saved_share = static_cast<double>(state->saved.blocks.size()) / blocks;
  }
  settings.progress = progress_reporter(render_start, messages, saved_share);
  settings.cancel = &interrupted;
  render::RenderResult rendered = render::render(scene, settings);
  r.times.render_s = seconds_since(render_start);
  if (r.times.render_s >= 1.0 && isatty(STDERR_FILENO) && messages.console(Stream::render)) std::cerr << "\n";
  r.rays = rendered.rays;
  if (rendered.cancelled && !write) {
    r.exit_status = 1;
    return r;
  }
  if (rendered.cancelled) {
    std::string text = "povtrace: interrupted; no image written (an existing output file is left as it was)";
    if (state) {
      try {
        state->writer->finish_interrupted(rendered.image);
        const long long kept = static_cast<long long>(state->saved.blocks.size()) + state->writer->blocks_recorded();
        text += "; " + std::to_string(kept) + " finished block" + (kept == 1 ? "" : "s") + " kept in '" +
                state->path.string() + "': +C continues the render";
      } catch (const std::exception& e) {
        messages.write(Stream::warning, std::string("povtrace: warning: ") + e.what() + "; +C may not continue all of it");
      }
    }
    messages.write(Stream::render, text);
    r.exit_status = 1;
    return r;
  }
  if (state) {   // the blocks of the interrupted render, as they were computed then
    for (const image::PixelRect& b : state->saved.blocks) {
      const std::size_t row = static_cast<std::size_t>(b.width()) * 4;
      for (int y = b.y0; y <= b.y1; ++y) {
        std::copy_n(state->saved.pixels.pixel(b.x0, y), row, rendered.image.pixel(b.x0, y));
      }
    }
  }
  if (!write) {
    r.image = std::move(rendered.image);
    return r;
  }
  finish_job(options, std::move(rendered.image), r, start, output, messages);
  if (state) state->writer->discard();   // the image is written: nothing left to continue
  return r;
}
}  // namespace

JobResult render_frame(const RenderOptions& options, const FramePlan& plan, const Frame& frame,
                       const std::atomic<bool>& interrupted, Messages& messages) {
  return render_one_frame(options, plan, frame, interrupted, messages, true);
}

JobResult render_frame_pixels(const RenderOptions& options, const FramePlan& plan, const Frame& frame,
                              const std::atomic<bool>& interrupted, Messages& messages) {
  return render_one_frame(options, plan, frame, interrupted, messages, false);
}

void finish_job(const RenderOptions& options, image::Image image, JobResult& r, Clock::time_point start,
                const std::filesystem::path& output, Messages& messages) {
  const auto write_start = Clock::now();
  if (options.write_file) {
    // +O- (POV-Ray also takes "stdout"): the whole file goes to standard output; messages stay on stderr.
    const bool to_stdout = output_to_stdout(options);
    r.output = to_stdout ? image::standard_output_path : output;
    image::write_image(image, r.output, resolved_encoding(options));
  }
  r.times.write_s = seconds_since(write_start);
  r.times.total_s = seconds_since(start);
  r.image = std::move(image);
  print_summary(options, r, messages);
  if (options.stats_json) {
    std::ofstream out(*options.stats_json);
    out << stats_json(options, r);
    if (!out) throw std::runtime_error("cannot write the stats file '" + options.stats_json->string() + "'");
  }
}

namespace {
std::string povray_command(const RenderOptions& o, const std::filesystem::path& exr) {
  std::ostringstream cmd;
  auto quote = [](const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
  };
  cmd << "povray -D -V +W" << o.width << " +H" << o.height;
  if (o.antialias) cmd << " +A" << o.antialias_threshold << " +R" << o.antialias_depth << " +AM" << o.sampling_method;
  else cmd << " -A";
  cmd << (o.jitter ? " +J" + std::to_string(o.jitter_amount) : std::string(" -J"));
  if (o.output_alpha) cmd << " +UA";
  if (o.quality != 9) cmd << " +Q" << o.quality;
  for (const auto& l : o.library_paths) cmd << " " << quote("+L" + l.string());
  for (const auto& [name, value] : o.declares) {
    char number[32];
    std::snprintf(number, sizeof number, "%.17g", value);   // exact round trip, not to_string's 6 decimals
    cmd << " " << quote("Declare=" + name + "=" + number);
  }
  cmd << " +FE " << quote("+O" + exr.string()) << " " << quote("+I" + o.input.string()) << " 2>&1";
  return cmd.str();
}
}  // namespace

int run_vs_povray(const RenderOptions& options, const std::atomic<bool>& interrupted) {
  RenderOptions ours = options;
  ours.write_file = false;
  ours.stats_json.reset();
  const auto ours_start = Clock::now();
  JobResult job = run_render(ours, interrupted);
  const double ours_wall = seconds_since(ours_start);
  if (job.exit_status != 0) return job.exit_status;

  const auto tmp = std::filesystem::temp_directory_path() / ("povtrace_vs_" + std::to_string(getpid()) + ".exr");
  const auto pov_start = Clock::now();
  const std::string command = povray_command(options, tmp);
  std::string log;
  if (FILE* pipe = popen(command.c_str(), "r")) {
    char buf[4096];
    while (std::fgets(buf, sizeof buf, pipe)) log += buf;
    const int status = pclose(pipe);
    if (status != 0 || !std::filesystem::exists(tmp)) {
      std::cerr << "povtrace: povray failed (is it installed? apt-get install povray):\n" << log;
      return 1;
    }
  } else {
    throw std::runtime_error("cannot run povray");
  }
  const double pov_wall = seconds_since(pov_start);
  const image::Image reference = image::read_image(tmp);
  std::filesystem::remove(tmp);

  const double threshold = 1.0 / 255.0;
  const image::CompareReport rep = image::compare_images(reference, job.image, threshold);
  const image::Image heat = image::difference_heat_map(reference, job.image, threshold);
  const image::Image strip = image::side_by_side({&job.image, &reference, &heat});
  std::filesystem::path out = options.output.value_or(options.input.stem().string() + "_vs_povray.png");
  image::write_image(strip, out, image::EncodeOptions{});

  std::printf("povtrace: %.3f s wall (render %.3f s)\npovray:   %.3f s wall\n", ours_wall, job.times.render_s, pov_wall);
  std::printf("RMSE %.6g  PSNR %.2f dB  max error %.6g at (%d,%d) channel %d  pixels over 1/255: %zu (%.4f %%)\n",
              rep.rmse, rep.psnr, rep.max_abs_error, rep.max_x, rep.max_y, rep.max_channel,
              rep.pixels_over_threshold, rep.share_over_threshold * 100);
  const bool pass = rep.psnr >= 50.0 && rep.share_over_threshold <= 0.001;
  std::string verdict = pass ? "match (PSNR >= 50 dB, <= 0.1 % of pixels off by more than 1/255)" : "DIFFERENT";
  if (!pass && !job.random_in_povray.empty()) {
    verdict += " - but POV-Ray draws this scene's ";
    for (std::size_t i = 0; i < job.random_in_povray.size(); ++i) {
      verdict += (i == 0 ? "" : i + 1 == job.random_in_povray.size() ? " and " : ", ") + job.random_in_povray[i];
    }
    verdict += " at random, so two POV-Ray renders differ too: compare against POV-Ray's own run-to-run spread";
  }
  std::printf("side by side (povtrace | POV-Ray | heat map): %s\nverdict: %s\n", out.string().c_str(), verdict.c_str());
  return pass ? 0 : 1;
}

}  // namespace povtrace::app

#include "app/mpi_render.hpp"

#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <iostream>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "app/animation.hpp"
#include "app/messages.hpp"
#include "app/region.hpp"
#include "app/render_job.hpp"
#include "renderer/object_geometry.hpp"
#include "renderer/render.hpp"
#include "renderer/render_scene.hpp"

namespace povtrace::app {
namespace {

using Clock = std::chrono::steady_clock;
using image::PixelRect;

// Messages between rank 0 and the workers.
enum Tag : int {
  tag_ready = 1,    // worker → 0: scene loaded, send work: double {parse seconds, build seconds}
  tag_tile = 2,     // 0 → worker: int32 {tile id, x0, y0, x1, y1}
  tag_result = 3,   // worker → 0: ResultHeader, then the tile's RGBA floats row by row (also asks for more work)
  tag_done = 4,     // 0 → worker: no more work (empty)
  tag_error = 5,    // worker → 0: the error's text
  // Frames mode (an animation): whole frames instead of tiles.
  tag_frame = 6,          // 0 → worker: int64 frame index in the plan's render order
  tag_frame_result = 7,   // worker → 0: FrameHeader; a tag_frame_pixels message follows
  tag_frame_pixels = 8,   // worker → 0: the frame's RGBA floats, row by row (MPI_FLOAT, so 2^28 pixels fit an int)
  tag_text = 9,           // worker → 0: the parse's #debug lines and warnings (pack_messages), written by rank 0
};

constexpr int tile_blocks = 4;     // a tile is 4 × 4 render blocks
constexpr auto poll_pause = std::chrono::milliseconds(1);

struct ResultHeader {
  std::int32_t tile = 0;
  std::int32_t floats = 0;
  std::uint64_t camera = 0, shadow = 0, secondary = 0;
};

struct Tile {
  PixelRect rect;
};

struct FrameHeader {
  std::int64_t index = 0;
  std::int32_t width = 0, height = 0, has_alpha = 0;
  std::uint64_t camera = 0, shadow = 0, secondary = 0;
  double parse_s = 0, build_s = 0, render_s = 0;
};

std::string tile_text(int id, const PixelRect& r) {
  char text[128];
  std::snprintf(text, sizeof text, "tile %d (columns %d-%d, rows %d-%d)", id, r.x0 + 1, r.x1 + 1, r.y0 + 1, r.y1 + 1);
  return text;
}

// Whole tile_blocks × tile_blocks groups of blocks of the (0,0) grid, clipped to the area, in reading order.
std::vector<Tile> make_tiles(const PixelRect& area, int block_size) {
  const int step = std::max(4, block_size) * tile_blocks;
  std::vector<Tile> tiles;
  for (int y = area.y0 / step * step; y <= area.y1; y += step) {
    for (int x = area.x0 / step * step; x <= area.x1; x += step) {
      tiles.push_back({{std::max(x, area.x0), std::max(y, area.y0), std::min(x + step - 1, area.x1),
                        std::min(y + step - 1, area.y1)}});
    }
  }
  return tiles;
}

[[noreturn]] void abort_job(const std::string& message) {
  std::cerr << "povtrace: MPI: " << message << "\npovtrace: MPI: job aborted, no image written\n" << std::flush;
  MPI_Abort(MPI_COMM_WORLD, 1);
  std::_Exit(1);   // MPI_Abort does not return; in case it does
}

// Waits (polling, sleeping between polls) for a message from `source`; returns its status.
MPI_Status wait_for_message(int source) {
  for (;;) {
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(source, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (flag) return status;
    std::this_thread::sleep_for(poll_pause);
  }
}

void send_error(const std::string& text) {
  MPI_Send(text.data(), static_cast<int>(text.size()), MPI_CHAR, 0, tag_error, MPI_COMM_WORLD);
}

// A worker's messages travel to rank 0, which alone writes the console and the +G files (one writer, as in a
// single process): per message its stream (one byte), its length (uint32) and its text.
void send_messages(const Messages::Captured& captured) {
  if (captured.empty()) return;
  std::vector<unsigned char> bytes;
  for (const auto& [stream, text] : captured) {
    const auto length = static_cast<std::uint32_t>(text.size());
    bytes.push_back(static_cast<unsigned char>(stream));
    bytes.insert(bytes.end(), reinterpret_cast<const unsigned char*>(&length),
                 reinterpret_cast<const unsigned char*>(&length) + sizeof length);
    bytes.insert(bytes.end(), text.begin(), text.end());
  }
  MPI_Send(bytes.data(), static_cast<int>(bytes.size()), MPI_BYTE, 0, tag_text, MPI_COMM_WORLD);
}

void replay_messages(const unsigned char* data, std::size_t size, Messages& messages) {
  std::size_t at = 0;
  while (at + 1 + sizeof(std::uint32_t) <= size) {
    const auto stream = static_cast<Stream>(data[at]);
    std::uint32_t length = 0;
    std::memcpy(&length, data + at + 1, sizeof length);
    at += 1 + sizeof length;
    if (length > size - at || data[at - 1 - sizeof length] > static_cast<unsigned char>(Stream::warning)) break;
    messages.write(stream, std::string(reinterpret_cast<const char*>(data + at), length));
    at += length;
  }
}

// Parse options whose #debug lines and warnings go to `messages` as a single process sends them.
void route_parse_messages(ParseOptions& parse_options, Messages& messages, DebugLines& debug_lines) {
  parse_options.classified_sink = [&messages, &debug_lines](ParseOptions::MessageKind kind, const std::string& text) {
    if (kind == ParseOptions::MessageKind::debug) debug_lines.add(text);
    else messages.write(Stream::warning, text);
  };
}

// ---- workers ------------------------------------------------------------------------------------------------------

// Tiles arrive already clipped to the region, so a worker needs no region of its own.
int run_worker(const RenderOptions& options, int rank, const std::atomic<bool>& interrupted) {
  std::optional<render::RenderScene> scene;
  double times[2] = {0, 0};   // parse, build
  Messages::Captured captured;
  Messages messages(captured);
  DebugLines debug_lines(messages);
  try {
    const auto start = Clock::now();
    ParseOptions parse_options = parse_options_from(options);
    parse_options.cancel = &interrupted;
    route_parse_messages(parse_options, messages, debug_lines);
    const FramePlan still = plan_frames(options.animation);   // a still: +K's clock, as one process parses it
    set_frame_values(still, still.at(0), parse_options);
    const SceneDescription description = parse_scene(options.input, parse_options);
    const auto parsed = Clock::now();
    times[0] = std::chrono::duration<double>(parsed - start).count();
    scene.emplace(render::build_render_scene(description,
                                             {options.output_alpha, options.povray_tolerances, options.specialise,
                                              render::Quality::quick_colours_at(options.quality), options.quality, options.threads}));
    times[1] = std::chrono::duration<double>(Clock::now() - parsed).count();
    for (const auto& w : scene->warnings) messages.write(Stream::warning, "povtrace: warning: " + w);
  } catch (const std::exception& e) {
    if (rank == 1) send_messages(captured);   // every worker parses the same scene: one speaks for all
    send_error(e.what());
  }
  if (scene && rank == 1) send_messages(captured);
  if (scene) MPI_Send(times, static_cast<int>(sizeof times), MPI_BYTE, 0, tag_ready, MPI_COMM_WORLD);

  render::RenderSettings settings = render_settings_from(options);
  settings.cancel = &interrupted;
  settings.crop_to_region = true;   // the result is the tile alone
  std::vector<unsigned char> buffer;
  for (;;) {
    MPI_Status status = wait_for_message(0);
    if (status.MPI_TAG == tag_done) {
      MPI_Recv(nullptr, 0, MPI_BYTE, 0, tag_done, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return 0;
    }
    std::int32_t t[5];
    MPI_Recv(t, 5, MPI_INT32_T, 0, tag_tile, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const PixelRect rect{t[1], t[2], t[3], t[4]};
    try {
      settings.region = rect;
      const render::RenderResult result = render::render(*scene, settings);
      if (result.cancelled) throw std::runtime_error("interrupted");
      ResultHeader header;
      header.tile = t[0];
      header.floats = rect.width() * rect.height() * 4;
      header.camera = result.rays.camera;
      header.shadow = result.rays.shadow;
      header.secondary = result.rays.secondary;
      buffer.resize(sizeof header + static_cast<std::size_t>(header.floats) * sizeof(float));
      std::memcpy(buffer.data(), &header, sizeof header);
      unsigned char* out = buffer.data() + sizeof header;
      std::memcpy(out, result.image.rgba.data(), result.image.rgba.size() * sizeof(float));
      MPI_Send(buffer.data(), static_cast<int>(buffer.size()), MPI_BYTE, 0, tag_result, MPI_COMM_WORLD);
    } catch (const std::exception& e) {
      send_error(tile_text(t[0], rect) + ": " + e.what());
    }
  }
}

// ---- rank 0 -------------------------------------------------------------------------------------------------------

// Tells every worker to finish. Only after the job succeeded: Open MPI 4.1.4's mpirun, asked by MPI_Abort to end a
// job while one rank is already inside MPI_Finalize, sometimes hangs in PMIx_server_finalize (or crashes), so a
// worker with nothing left to do waits for this message instead of finalizing (tests/mpi/killed_worker.sh STOP).
void release_workers(int ranks) {
  for (int w = 1; w < ranks; ++w) MPI_Send(nullptr, 0, MPI_BYTE, w, tag_done, MPI_COMM_WORLD);
}

// The deadline for one piece of work: POVTRACE_MPI_TILE_TIMEOUT seconds when set, else max(floor, 10 × the
// slowest piece so far).
double work_timeout(double slowest, double floor) {
  if (const char* text = std::getenv("POVTRACE_MPI_TILE_TIMEOUT")) {
    char* end = nullptr;
    const double v = std::strtod(text, &end);
    if (end != text && v > 0) return v;
  }
  return std::max(floor, 10.0 * slowest);
}

double tile_timeout(double slowest) { return work_timeout(slowest, 60.0); }

int run_master(const RenderOptions& options, const std::optional<PixelRect>& region, int ranks,
               const std::atomic<bool>& interrupted) {
  const auto start = Clock::now();
  const render::RenderSettings settings = render_settings_from(options);
  const PixelRect area = region.value_or(PixelRect{0, 0, options.width - 1, options.height - 1});
  const std::vector<Tile> tiles = make_tiles(area, settings.block_size);

  image::Image image(options.width, options.height);   // black and opaque outside a region, as render() leaves it
  image.has_alpha = options.output_alpha;
  image.region = region;
  JobResult job;
  Messages messages(options.streams);

  struct Busy {
    int tile = -1;
    Clock::time_point since;
  };
  std::vector<Busy> busy(static_cast<std::size_t>(ranks));
  std::size_t next = 0, finished = 0;
  double slowest = 0;
  std::vector<unsigned char> buffer;
  std::vector<bool> idle(static_cast<std::size_t>(ranks), false);

  // Gives `worker` the next tile, or leaves it idle when none is left.
  auto hand_out = [&](int worker) {
    if (next < tiles.size()) {
      const PixelRect& r = tiles[next].rect;
      const std::int32_t t[5] = {static_cast<std::int32_t>(next), r.x0, r.y0, r.x1, r.y1};
      busy[static_cast<std::size_t>(worker)] = {static_cast<int>(next), Clock::now()};
      ++next;
      MPI_Send(t, 5, MPI_INT32_T, worker, tag_tile, MPI_COMM_WORLD);
    } else {
      busy[static_cast<std::size_t>(worker)].tile = -1;
      idle[static_cast<std::size_t>(worker)] = true;   // released only once the image is written
    }
  };

  int last_quarter = 0;
  while (finished < tiles.size()) {
    if (interrupted.load()) abort_job("interrupted");
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) {
      const double timeout = tile_timeout(slowest);
      for (int w = 1; w < ranks; ++w) {
        const Busy& b = busy[static_cast<std::size_t>(w)];
        if (b.tile >= 0 && std::chrono::duration<double>(Clock::now() - b.since).count() > timeout) {
          char seconds[32];
          std::snprintf(seconds, sizeof seconds, "%.0f", timeout);
          abort_job("rank " + std::to_string(w) + " did not finish " +
                    tile_text(b.tile, tiles[static_cast<std::size_t>(b.tile)].rect) + " within " + seconds +
                    " s (dead or stuck)");
        }
      }
      std::this_thread::sleep_for(poll_pause);
      continue;
    }
    const int source = status.MPI_SOURCE;
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    buffer.resize(static_cast<std::size_t>(std::max(bytes, 1)));
    MPI_Recv(buffer.data(), bytes, MPI_BYTE, source, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const Busy was = busy[static_cast<std::size_t>(source)];
    if (status.MPI_TAG == tag_error) {
      const std::string text(buffer.begin(), buffer.begin() + bytes);
      abort_job("rank " + std::to_string(source) + " failed: " + text);
    }
    if (status.MPI_TAG == tag_result) {
      ResultHeader h;
      if (static_cast<std::size_t>(bytes) < sizeof h) abort_job("rank " + std::to_string(source) + ": short result");
      std::memcpy(&h, buffer.data(), sizeof h);
      if (h.tile != was.tile || h.tile < 0) abort_job("rank " + std::to_string(source) + ": result for an unexpected tile");
      const PixelRect& r = tiles[static_cast<std::size_t>(h.tile)].rect;
      if (h.floats != r.width() * r.height() * 4 ||
          static_cast<std::size_t>(bytes) != sizeof h + static_cast<std::size_t>(h.floats) * sizeof(float)) {
        abort_job("rank " + std::to_string(source) + ": " + tile_text(h.tile, r) + " has the wrong size");
      }
      const unsigned char* in = buffer.data() + sizeof h;
      const std::size_t row_bytes = static_cast<std::size_t>(r.width()) * 4 * sizeof(float);
      for (int y = r.y0; y <= r.y1; ++y, in += row_bytes) std::memcpy(image.pixel(r.x0, y), in, row_bytes);
      job.rays += render::RayCounts{h.camera, h.shadow, h.secondary};
      slowest = std::max(slowest, std::chrono::duration<double>(Clock::now() - was.since).count());
      ++finished;
      if (options.verbose && static_cast<int>(4 * finished / tiles.size()) > last_quarter) {
        last_quarter = static_cast<int>(4 * finished / tiles.size());
        std::cerr << "povtrace: MPI: " << finished << " of " << tiles.size() << " tiles\n";
      }
    } else if (status.MPI_TAG == tag_text) {
      replay_messages(buffer.data(), static_cast<std::size_t>(bytes), messages);
      continue;   // the worker's ready (or error) follows
    } else if (status.MPI_TAG == tag_ready && static_cast<std::size_t>(bytes) == 2 * sizeof(double)) {
      double times[2];
      std::memcpy(times, buffer.data(), sizeof times);   // the slowest worker's, as the summary's parse and build
      job.times.parse_s = std::max(job.times.parse_s, times[0]);
      job.times.build_s = std::max(job.times.build_s, times[1]);
    } else {
      abort_job("rank " + std::to_string(source) + ": unexpected message tag " + std::to_string(status.MPI_TAG));
    }
    hand_out(source);
  }
  // Workers still loading the scene (more ranks than tiles) are waited for, so that none is left reporting.
  for (int w = 1; w < ranks; ++w) {
    if (idle[static_cast<std::size_t>(w)]) continue;
    for (;;) {
      MPI_Status status = wait_for_message(w);
      int bytes = 0;
      MPI_Get_count(&status, MPI_BYTE, &bytes);
      buffer.resize(static_cast<std::size_t>(std::max(bytes, 1)));
      MPI_Recv(buffer.data(), bytes, MPI_BYTE, w, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      if (status.MPI_TAG == tag_error) {
        abort_job("rank " + std::to_string(w) + " failed: " + std::string(buffer.begin(), buffer.begin() + bytes));
      }
      if (status.MPI_TAG != tag_text) break;   // its ready
      replay_messages(buffer.data(), static_cast<std::size_t>(bytes), messages);
    }
  }
  // Rank 0's wall time less the slowest worker's parse and build (which ran before its first tile).
  job.times.render_s = std::max(0.0, std::chrono::duration<double>(Clock::now() - start).count() -
                                         job.times.parse_s - job.times.build_s);
  try {
    finish_job(options, std::move(image), job, start, resolved_output_path(options), messages);
  } catch (const std::exception& e) {
    abort_job(std::string("cannot write the image: ") + e.what());
  }
  release_workers(ranks);
  return 0;
}

// ---- frames mode (an animation) -----------------------------------------------------------------------------------
// Each frame is parsed (with its clock), built and rendered whole by one worker, exactly as one process renders it
// (render_frame_pixels); its pixels go to rank 0, which writes the numbered file through finish_job. Frames are
// handed out in render order, one at a time as workers report; files are written in the order frames finish.

int run_frame_worker(const RenderOptions& options, const FramePlan& plan, const std::atomic<bool>& interrupted) {
  Messages::Captured captured;   // each frame's #debug lines and warnings, sent to rank 0 before its pixels
  Messages messages(captured);
  const double no_times[2] = {0, 0};   // nothing is loaded up front: each frame parses its own scene
  MPI_Send(no_times, static_cast<int>(sizeof no_times), MPI_BYTE, 0, tag_ready, MPI_COMM_WORLD);
  for (;;) {
    MPI_Status status = wait_for_message(0);
    if (status.MPI_TAG == tag_done) {
      MPI_Recv(nullptr, 0, MPI_BYTE, 0, tag_done, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      return 0;
    }
    std::int64_t index = 0;
    MPI_Recv(&index, 1, MPI_INT64_T, 0, tag_frame, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    const Frame frame = plan.at(index);
    captured.clear();
    try {
      JobResult r = render_frame_pixels(options, plan, frame, interrupted, messages);
      if (r.exit_status != 0) throw std::runtime_error("interrupted");
      send_messages(captured);
      FrameHeader h;
      h.index = index;
      h.width = r.image.width;
      h.height = r.image.height;
      h.has_alpha = r.image.has_alpha ? 1 : 0;
      h.camera = r.rays.camera;
      h.shadow = r.rays.shadow;
      h.secondary = r.rays.secondary;
      h.parse_s = r.times.parse_s;
      h.build_s = r.times.build_s;
      h.render_s = r.times.render_s;
      MPI_Send(&h, static_cast<int>(sizeof h), MPI_BYTE, 0, tag_frame_result, MPI_COMM_WORLD);
      MPI_Send(r.image.rgba.data(), static_cast<int>(r.image.rgba.size()), MPI_FLOAT, 0, tag_frame_pixels,
               MPI_COMM_WORLD);
    } catch (const std::exception& e) {
      send_messages(captured);
      send_error("frame " + std::to_string(frame.number) + ": " + e.what());
    }
  }
}

int run_frame_master(const RenderOptions& options, const FramePlan& plan, const std::optional<PixelRect>& region,
                     int ranks, const std::atomic<bool>& interrupted) {
  Messages messages(options.streams);
  const ShellCommands& c = options.shell_commands;
  const bool any_command = !(c.pre_scene.command.empty() && c.post_scene.command.empty() && c.pre_frame.command.empty() &&
                             c.post_frame.command.empty() && c.user_abort.command.empty() &&
                             c.fatal_error.command.empty());
  if (any_command) {
    messages.write(Stream::warning,
                   "povtrace: warning: the *_Command shell-outs are not run in an MPI render (run them around mpirun)");
  }
  const long long total = plan.count();
  struct Busy {
    long long index = -1;
    Clock::time_point since;
  };
  std::vector<Busy> busy(static_cast<std::size_t>(ranks));
  std::vector<bool> idle(static_cast<std::size_t>(ranks), false);
  long long next = 0, finished = 0;
  double slowest = 0;
  auto hand_out = [&](int worker) {
    Busy& b = busy[static_cast<std::size_t>(worker)];
    if (next < total) {
      const std::int64_t index = next++;
      b = {index, Clock::now()};
      MPI_Send(&index, 1, MPI_INT64_T, worker, tag_frame, MPI_COMM_WORLD);
    } else {
      b.index = -1;
      idle[static_cast<std::size_t>(worker)] = true;   // released only once every frame is written
    }
  };
  std::vector<unsigned char> buffer;
  while (finished < total || std::find(idle.begin() + 1, idle.end(), false) != idle.end()) {
    if (interrupted.load()) abort_job("interrupted");
    int flag = 0;
    MPI_Status status;
    MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &flag, &status);
    if (!flag) {
      // A frame parses and renders a whole scene: ten minutes at least before a worker counts as stuck.
      const double timeout = work_timeout(slowest, 600.0);
      for (int w = 1; w < ranks; ++w) {
        const Busy& b = busy[static_cast<std::size_t>(w)];
        if (b.index >= 0 && std::chrono::duration<double>(Clock::now() - b.since).count() > timeout) {
          char seconds[32];
          std::snprintf(seconds, sizeof seconds, "%.0f", timeout);
          abort_job("rank " + std::to_string(w) + " did not finish frame " + std::to_string(plan.at(b.index).number) +
                    " within " + seconds + " s (dead or stuck)");
        }
      }
      std::this_thread::sleep_for(poll_pause);
      continue;
    }
    const int source = status.MPI_SOURCE;
    int bytes = 0;
    MPI_Get_count(&status, MPI_BYTE, &bytes);
    if (status.MPI_TAG == tag_frame_result) {
      FrameHeader h;
      if (bytes != static_cast<int>(sizeof h)) abort_job("rank " + std::to_string(source) + ": bad frame header");
      MPI_Recv(&h, bytes, MPI_BYTE, source, tag_frame_result, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      const Busy was = busy[static_cast<std::size_t>(source)];
      if (h.index != was.index || h.width != options.width || h.height != options.height) {
        abort_job("rank " + std::to_string(source) + ": a result for an unexpected frame or size");
      }
      image::Image image(h.width, h.height);
      image.has_alpha = h.has_alpha != 0;
      image.region = region;
      MPI_Recv(image.rgba.data(), static_cast<int>(image.rgba.size()), MPI_FLOAT, source, tag_frame_pixels,
               MPI_COMM_WORLD, MPI_STATUS_IGNORE);
      slowest = std::max(slowest, std::chrono::duration<double>(Clock::now() - was.since).count());
      JobResult job;
      job.rays = render::RayCounts{h.camera, h.shadow, h.secondary};
      job.times.parse_s = h.parse_s;
      job.times.build_s = h.build_s;
      job.times.render_s = h.render_s;
      const Frame frame = plan.at(h.index);
      const auto worked = std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(h.parse_s + h.build_s + h.render_s));
      try {
        finish_job(options, std::move(image), job, Clock::now() - worked,
                   frame_output_path(resolved_output_path(options), plan, frame.number), messages);
      } catch (const std::exception& e) {
        abort_job("cannot write frame " + std::to_string(frame.number) + ": " + e.what());
      }
      ++finished;
      hand_out(source);
      continue;
    }
    buffer.resize(static_cast<std::size_t>(std::max(bytes, 1)));
    MPI_Recv(buffer.data(), bytes, MPI_BYTE, source, status.MPI_TAG, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    if (status.MPI_TAG == tag_error) {
      abort_job("rank " + std::to_string(source) + " failed: " + std::string(buffer.begin(), buffer.begin() + bytes));
    }
    if (status.MPI_TAG == tag_text) {   // a frame's #debug lines and warnings; its result follows
      replay_messages(buffer.data(), static_cast<std::size_t>(bytes), messages);
      continue;
    }
    if (status.MPI_TAG != tag_ready) {
      abort_job("rank " + std::to_string(source) + ": unexpected message tag " + std::to_string(status.MPI_TAG));
    }
    hand_out(source);
  }
  release_workers(ranks);
  return 0;
}

}  // namespace

bool mpi_launched() {
  for (const char* name : {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE"}) {
    if (const char* value = std::getenv(name)) return std::atoi(value) > 1;
  }
  return false;
}

int run_mpi_render(const RenderOptions& options, const std::atomic<bool>& interrupted) {
  // Checked before MPI starts, so every rank reports a bad region the same way (exit 2).
  const std::optional<PixelRect> region = resolve_region(options.region, options.width, options.height);
  if (options.input == "-") {   // mpirun passes standard input to rank 0 only, and every worker parses the scene
    throw UsageError("+I- (the scene from standard input) cannot be used under mpirun: give the scene file");
  }
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);   // only this thread calls MPI
  int rank = 0, ranks = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &ranks);
  int status = 0;
  if (ranks < 2) {
    MPI_Finalize();
    throw std::runtime_error("MPI: one rank only; run without mpirun");
  }
  if (rank == 0 && options.continue_trace) {
    std::cerr << "povtrace: warning: +C (Continue_Trace) has no effect under mpirun: the MPI path keeps no render "
                 "state file; rendering from the start\n";
  }
  // A worker writes no file, so a SIGTERM or SIGINT (mpirun's teardown after MPI_Abort sends SIGCONT, SIGTERM,
  // then SIGKILL) ends it at once instead of cancelling its tile and reporting to a rank 0 that is gone.
  if (rank != 0) {
    std::signal(SIGTERM, SIG_DFL);
    std::signal(SIGINT, SIG_DFL);
  }
  // An animation is split by frames (each parsed with its own clock), a still by tiles.
  const FramePlan plan = plan_frames(options.animation);
  if (plan.animated) {
    if (rank == 0) status = run_frame_master(options, plan, region, ranks, interrupted);
    else status = run_frame_worker(options, plan, interrupted);
  } else if (rank == 0) {
    status = run_master(options, region, ranks, interrupted);
  } else {
    status = run_worker(options, rank, interrupted);
  }
  MPI_Finalize();
  return status;
}

}  // namespace povtrace::app

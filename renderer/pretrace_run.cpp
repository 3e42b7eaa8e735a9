#include "renderer/pretrace_run.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <thread>
#include <vector>

#include "renderer/radiosity/pretrace.hpp"

namespace povtrace::render {

namespace {
using radiosity::BlockRect;
using radiosity::PretraceBlockState;

// Calls work(thread, item) for every item in [0, items) on `threads` threads, items handed out in order.
template <class Work>
void parallel_items(int threads, int items, Work&& work) {
  std::atomic<int> next{0};
  auto loop = [&](int thread) {
    for (int i = next++; i < items; i = next++) work(thread, i);
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t) pool.emplace_back(loop, t);
  loop(0);
  for (std::thread& t : pool) t.join();
}

// One pass of one block (radiositytask.cpp's block loop): its sub-blocks still incomplete, each traced at its
// jittered points and judged by the depth-0 statistics of its rays; the block's state advances one pass.
void pretrace_block(Tracer& tracer, const RenderScene& scene, const RenderSettings& settings, int serial,
                    const BlockRect& rect, PretraceBlockState& state, const std::vector<double>& sizes,
                    double end_size) {
  radiosity::Gatherer& gatherer = *tracer.gatherer();
  const int coverage = scene.radiosity->settings.nearest_count_adaptive;
  const int pass_id = state.pass + 1;
  const double size = sizes[static_cast<std::size_t>(state.pass)];
  const double next_size = std::max(sizes.front() * std::pow(0.5, state.pass + 1), end_size);
  const int split_x = radiosity::pretrace_split(rect.width(), next_size, state.sub_count_x, coverage);
  const int split_y = radiosity::pretrace_split(rect.height(), next_size, state.sub_count_y, coverage);
  radiosity::PretraceJitter jitter;
  jitter.seed(pass_id, serial);
  tracer.forget_shadow_cache();
  const std::size_t subs = state.incomplete.size();
  for (std::size_t i = 0; i < subs; ++i) {
    gatherer.reset_top_level_stats();
    const radiosity::SubBlock sub = state.incomplete.front();
    state.incomplete.pop_front();
    const std::vector<radiosity::PretracePoint> points =
        radiosity::pretrace_points(rect, state, sub, size, jitter);
    for (const radiosity::PretracePoint& p : points)
      if (const std::optional<Ray> ray = camera_ray(scene.camera, p.x, p.y, settings.width, settings.height))
        (void)tracer.trace_camera_ray(*ray, true);
    if (radiosity::pretrace_again(static_cast<int>(points.size()), gatherer.top_level_queries(),
                                  gatherer.top_level_reuse(), coverage))
      for (int y = 0; y < split_y; ++y)
        for (int x = 0; x < split_x; ++x) state.incomplete.push_back({sub.x * split_x + x, sub.y * split_y + y});
  }
  ++state.pass;
  if (!state.finished(static_cast<int>(sizes.size()))) {
    state.sub_count_x *= split_x;
    state.sub_count_y *= split_y;
  }
}
}  // namespace

PretraceResult run_pretrace(const RenderScene& scene, const RenderSettings& settings, int threads) {
  PretraceResult result;
  const RadiositySettings& rs = scene.radiosity->settings;
  const std::vector<double> sizes =
      radiosity::pretrace_cell_sizes(settings.width, settings.height, rs.pretrace_start, rs.pretrace_end);
  const int passes = static_cast<int>(sizes.size());
  if (passes == 0) return result;   // pretrace_start below one pixel: POV-Ray traces no pretrace
  const double end_size = std::max(1.0, std::max(settings.width, settings.height) * rs.pretrace_end);
  const int bs = std::max(4, settings.block_size);
  const int across = (settings.width + bs - 1) / bs, down = (settings.height + bs - 1) / bs;
  const int blocks = across * down;
  std::vector<BlockRect> rects(static_cast<std::size_t>(blocks));
  for (int b = 0; b < blocks; ++b) {
    const int x0 = (b % across) * bs, y0 = (b / across) * bs;
    rects[static_cast<std::size_t>(b)] = {x0, y0, std::min(x0 + bs, settings.width) - 1,
                                          std::min(y0 + bs, settings.height) - 1};
  }
  std::vector<PretraceBlockState> states(static_cast<std::size_t>(blocks));
  const bool one_order = settings.radiosity_povray_order;
  if (one_order) threads = 1;
  std::vector<std::unique_ptr<Tracer>> tracers;
  for (int t = 0; t < threads; ++t)
    tracers.push_back(std::make_unique<Tracer>(scene, settings.shading, Quality::at_level(settings.quality)));
  std::atomic<bool> cancelled{false};

  for (int pass = 0; pass < passes && !cancelled; ++pass) {
    const int groups = one_order ? 1 : std::min(blocks, 1 << std::min(pass, 20));
    std::vector<radiosity::CacheLevel> made(static_cast<std::size_t>(groups));
    parallel_items(std::min(threads, groups), groups, [&](int thread, int group) {
      Tracer& tracer = *tracers[static_cast<std::size_t>(thread)];
      if (!one_order) {
        tracer.gatherer()->set_global(&result.cache);
        tracer.begin_block(group, pass + 1);
      } else if (pass == 0) {
        tracer.begin_block(0, 1);   // POV-Ray's one task: tile 0, its samples all in its own level
      } else {
        tracer.gatherer()->set_pass(pass + 1);
      }
      for (int serial = group; serial < blocks; serial += groups) {
        if (cancelled || (settings.cancel && settings.cancel->load())) {
          cancelled = true;
          return;
        }
        PretraceBlockState& state = states[static_cast<std::size_t>(serial)];
        if (state.pass == pass && !state.finished(passes))
          pretrace_block(tracer, scene, settings, serial, rects[static_cast<std::size_t>(serial)], state, sizes,
                         end_size);
      }
      if (!one_order) made[static_cast<std::size_t>(group)] = tracer.gatherer()->block_samples();
    });
    radiosity::merge_blocks(result.cache, std::span<radiosity::CacheLevel>(made));
  }
  if (one_order) result.cache = tracers.front()->gatherer()->block_samples();
  for (const auto& t : tracers) result.rays += t->counts();
  result.cancelled = cancelled;
  return result;
}

}  // namespace povtrace::render

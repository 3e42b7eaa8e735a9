#include "renderer/pretrace_run.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "renderer/focal_blur.hpp"
#include "renderer/radiosity/pretrace.hpp"

namespace povtrace::render {

namespace {
using radiosity::BlockRect;
using radiosity::PretraceBlockState;

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
  const std::size_t subs = state.incomplete.size();
  for (std::size_t i = 0; i < subs; ++i) {
    gatherer.reset_top_level_stats();
    const radiosity::SubBlock sub = state.incomplete.front();
    state.incomplete.pop_front();
    const std::vector<radiosity::PretracePoint> points =
        radiosity::pretrace_points(rect, state, sub, size, jitter);
    for (const radiosity::PretracePoint& p : points) {
      if (scene.camera.focal_blur) {   // POV-Ray's pretrace traces its points as pixels: through the lens too
        (void)focal_blur_sample(scene.camera, settings.width, settings.height, p.x, p.y,
                                [&](const Ray& ray) { return tracer.trace_camera_ray(ray, true); });
        continue;
      }
      for (unsigned n = 0; n < camera_rays_per_pixel(scene.camera); ++n)   // a mesh camera's rays per pixel
        if (const std::optional<Ray> ray = camera_ray(scene.camera, p.x, p.y, settings.width, settings.height, n))
          (void)tracer.trace_camera_ray(*ray, true);
    }
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

PretraceResult run_pretrace(const RenderScene& scene, const RenderSettings& settings) {
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
  std::vector<PretraceBlockState> states(static_cast<std::size_t>(blocks));
  Tracer tracer(scene, settings.shading, Quality::at_level(settings.quality));
  tracer.begin_block(0, 1);   // POV-Ray's one pretrace task: tile 0 throughout, its samples all in its own level
  for (int pass = 0; pass < passes; ++pass) {
    if (pass > 0) tracer.gatherer()->set_pass(pass + 1);
    for (int serial = 0; serial < blocks; ++serial) {
      if (settings.cancel && settings.cancel->load()) {
        result.cancelled = true;
        return result;
      }
      PretraceBlockState& state = states[static_cast<std::size_t>(serial)];
      if (state.finished(passes)) continue;
      const int x0 = (serial % across) * bs, y0 = (serial / across) * bs;
      const BlockRect rect{x0, y0, std::min(x0 + bs, settings.width) - 1, std::min(y0 + bs, settings.height) - 1};
      pretrace_block(tracer, scene, settings, serial, rect, state, sizes, end_size);
    }
  }
  result.cache = tracer.gatherer()->block_samples();
  result.rays = tracer.counts();
  return result;
}

}  // namespace povtrace::render

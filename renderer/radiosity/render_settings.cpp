#include "renderer/radiosity/render_settings.hpp"

#include <algorithm>
#include <cmath>

#include "renderer/radiosity/weights.hpp"

namespace povtrace::render::radiosity {

DepthSettings depth_settings(const RadiositySettings& s, int depth) {
  DepthSettings d;
  const double factor = std::pow(2.0, static_cast<double>(depth));
  d.rays = std::min(std::max(5, static_cast<int>(s.count * std::pow(0.5, static_cast<double>(depth)))),
                    s.direction_pool);
  d.reuse_count = reuse_count(s.nearest_count, depth);
  d.error_bound_factor = 1.0 * factor;
  d.minimum_reuse = s.minimum_reuse * factor;
  d.maximum_reuse = s.maximum_reuse * factor;
  d.trace_level = static_cast<int>(1.5 * (static_cast<double>(depth) + 1));
  d.weight = std::pow(0.5 * s.brightness, static_cast<double>(depth) + 1);
  return d;
}

RenderRadiosity make_render_radiosity(const SceneDescription& scene) {
  const RadiositySettings& s = *scene.radiosity;
  RenderRadiosity r{s, {}, DirectionPool(static_cast<std::size_t>(s.direction_pool)), true, 1.0f};
  for (int d = 0; d < s.recursion_limit; ++d) r.depths.push_back(depth_settings(s, d));
  r.drop_ambient = scene.effective_language_version() >= 370;
  r.default_importance = static_cast<float>(scene.radiosity_default_importance);
  return r;
}

}  // namespace povtrace::render::radiosity

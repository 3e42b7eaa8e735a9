// The render-ready form of global_settings { radiosity { … } } (docs/issue19-study.md §1): the parsed settings,
// the values POV-Ray derives from them per bounce depth (radiosity.cpp SceneRadiositySettings::
// GetRecursionSettings), the direction pool and each object's importance. Built once with the RenderScene and
// read-only afterwards.
#pragma once

#include <vector>

#include "renderer/radiosity/directions.hpp"
#include "scene/description.hpp"

namespace povtrace::render::radiosity {

// What POV-Ray precomputes for bounce depth d (0 ≤ d < recursion_limit), study §1 "Derived per depth".
struct DepthSettings {
  int rays = 35;                  // max(5, ⌊count·0.5^d⌋), capped at the pool size (study §4.1)
  int reuse_count = 5;            // weights.hpp reuse_count
  double error_bound_factor = 1;  // 2^d
  double minimum_reuse = 0.015;   // minimum_reuse·2^d (times the distance to the camera)
  double maximum_reuse = 0.2;     // maximum_reuse·2^d
  int trace_level = 1;            // ⌊1.5·(d+1)⌋: POV-Ray's trace level of the sample rays shot from depth d
  double weight = 0.5;            // (0.5·brightness)^(d+1): their base weight
};

struct RenderRadiosity {
  RadiositySettings settings;
  std::vector<DepthSettings> depths;   // one per depth below recursion_limit
  DirectionPool pool;
  // A layer's `ambient · ambient_light` is dropped (trace.cpp ComputeLightedTexture): the scene's effective
  // language version is 3.7 or later (study §1.1). Older scenes keep it as a light source too.
  bool drop_ambient = true;
  // The final #default { radiosity { importance } }: the importance of a miss and of every object that wrote none
  // (study §1.3), which a sample ray compares with its share i/(n−1) at its first hit (§4.4). An object's own is
  // Primitive::radiosity_importance.
  float default_importance = 1;
};

// The derived values of depth d, as GetRecursionSettings computes them.
DepthSettings depth_settings(const RadiositySettings& s, int depth);

// Everything above from the scene. The pool has count's second value M entries (the Halton pool also for
// M < 1600, where POV-Ray reads its legacy table: the caller warns, study §5.4).
RenderRadiosity make_render_radiosity(const SceneDescription& scene);

}  // namespace povtrace::render::radiosity

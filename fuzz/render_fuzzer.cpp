// libFuzzer target for the whole pipeline: arbitrary bytes as a scene file, parsed, built and rendered at 8×6 on
// one thread. A ParseError (bad or unsupported input, wherever it is found) is the expected outcome of most
// inputs; any other exception, a crash, a sanitizer report or a non-finite pixel is a finding.
// Built by scripts/fuzz.sh (clang, -DPOVTRACE_FUZZ=ON); see fuzz/CMakeLists.txt.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <string>
#include <variant>

#include "parser/parse_scene.hpp"
#include "renderer/object_geometry.hpp"
#include "renderer/pattern_evaluator.hpp"
#include "renderer/render.hpp"
#include "renderer/render_scene.hpp"

namespace {
const povtrace::ParseOptions& fuzz_options() {
  static const povtrace::ParseOptions options = [] {
    povtrace::ParseOptions o;
    o.message_sink = [](const std::string&) {};   // #debug and warnings are dropped
    o.max_tokens = 200000;                          // every input ends (a runaway #while is legal SDL)
    // trace(), inside() and pattern functions as povtrace runs them
    o.object_geometry = std::make_shared<povtrace::render::RendererGeometry>();
    o.pattern_evaluator = std::make_shared<povtrace::render::RendererPatterns>();
    return o;
  }();
  return options;
}

// Julia fractals march in steps of 1/precision with max_iteration iterations each, and a bicubic patch makes
// 2^(u_steps + v_steps) pieces: both kept small here, in every object of the tree.
void bound_shapes(povtrace::Object& o) {
  if (auto* j = std::get_if<povtrace::JuliaFractal>(&o.shape)) {
    j->max_iteration = std::min(j->max_iteration, 30);
    j->precision = std::max(j->precision, 1.0 / 100.0);
  }
  if (auto* b = std::get_if<povtrace::BicubicPatch>(&o.shape)) {
    b->u_steps = std::min(b->u_steps, 4);
    b->v_steps = std::min(b->v_steps, 4);
  }
  if (auto* csg = std::get_if<povtrace::Csg>(&o.shape))
    for (povtrace::Object& child : csg->children) bound_shapes(child);
  for (auto* list : {&o.clipped_by, &o.bounded_by})
    for (povtrace::Object& inner : *list) bound_shapes(inner);
}

// Keeps each input's render cheap (legal but slow settings are not what this target looks for): a shallow trace,
// small area-light grids, and small julia fractal and bicubic patch settings.
void bound_the_work(povtrace::SceneDescription& scene) {
  scene.settings.max_trace_level = std::min(scene.settings.max_trace_level, 5);
  for (povtrace::Light& l : scene.lights) {
    l.size1 = std::min(l.size1, 4);
    l.size2 = std::min(l.size2, 4);
  }
  for (povtrace::Object& o : scene.objects) bound_shapes(o);
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    povtrace::SceneDescription scene = povtrace::parse_scene_text(text, "fuzz.pov", fuzz_options());
    if (scene.objects.size() > 2000) return 0;
    bound_the_work(scene);
    const povtrace::render::RenderScene built = povtrace::render::build_render_scene(scene, {});
    povtrace::render::RenderSettings settings;
    settings.width = 8;
    settings.height = 6;
    settings.threads = 1;
    const povtrace::render::RenderResult out = povtrace::render::render(built, settings);
    for (const float v : out.image.rgba)
      if (!std::isfinite(v)) std::abort();   // a NaN or infinite pixel is a finding
  } catch (const povtrace::ParseError&) {
    // a located error: bad input reported as it should be
  }
  return 0;
}

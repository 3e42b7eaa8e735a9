#include "renderer/pattern_evaluator.hpp"

#include <array>

#include "renderer/pattern/pattern.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {

// POV-Ray's f_pattern: the point through the pattern's transforms and warps (Warp_EPoint), then the pattern and
// its frequency/phase/wave step (Evaluate_TPat). No colour map is looked at.
class RendererPattern final : public PreparedPattern {
 public:
  explicit RendererPattern(const Pigment& p) {
    const RenderPigment built = build_render_pigment(p);
    for (int g = 0; g < 3; ++g) {   // one copy per noise generator, chosen when the function runs
      by_generator_[static_cast<std::size_t>(g)] = built;
      set_generator(by_generator_[static_cast<std::size_t>(g)], static_cast<NoiseGenerator>(g + 1));
    }
  }
  double value(Vec3 point, int noise_generator) const override {
    const int g = noise_generator >= 1 && noise_generator <= 3 ? noise_generator : 2;
    const RenderPigment& r = by_generator_[static_cast<std::size_t>(g - 1)];
    return apply_wave(pattern_value(r.params, to_pattern_space(r, point)), r.wave);
  }

 private:
  std::array<RenderPigment, 3> by_generator_;
};

class RendererPatterns final : public PatternEvaluator {
 public:
  std::variant<std::shared_ptr<const PreparedPattern>, std::string> prepare(const Pigment& p) const override {
    switch (p.pattern) {
      case PatternKind::solid: return std::string("a pattern function without a pattern");
      case PatternKind::average: return std::string("the pattern 'average' in a pattern function");
      case PatternKind::image_map: return std::string("the pattern 'image_map' in a pattern function");
      case PatternKind::uv_mapping: return std::string("uv_mapping in a pattern function");
      default: break;
    }
    return std::shared_ptr<const PreparedPattern>(std::make_shared<RendererPattern>(p));
  }
};

}  // namespace

std::shared_ptr<const PatternEvaluator> pattern_evaluator() {
  static const std::shared_ptr<const PatternEvaluator> evaluator = std::make_shared<RendererPatterns>();
  return evaluator;
}

}  // namespace povtrace::render

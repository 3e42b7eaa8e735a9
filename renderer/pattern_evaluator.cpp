#include "renderer/pattern_evaluator.hpp"

#include <array>

#include "renderer/pattern/pattern.hpp"
#include "renderer/pattern/render_pigment.hpp"
#include "renderer/tracer.hpp"

namespace povtrace::render {

namespace {

// A built pigment in one copy per noise generator (1 to 3), since the scene's generator is read when a function
// runs, not when it is prepared; anything else counts as 2, POV-Ray's default.
class PigmentPerGenerator {
 public:
  explicit PigmentPerGenerator(const Pigment& p) {
    const RenderPigment built = build_render_pigment(p);
    for (int g = 0; g < 3; ++g) {
      copies_[static_cast<std::size_t>(g)] = built;
      set_generator(copies_[static_cast<std::size_t>(g)], static_cast<NoiseGenerator>(g + 1));
    }
  }
  const RenderPigment& with(int noise_generator) const {
    const int g = noise_generator >= 1 && noise_generator <= 3 ? noise_generator : 2;
    return copies_[static_cast<std::size_t>(g - 1)];
  }

 private:
  std::array<RenderPigment, 3> copies_;
};

// POV-Ray's f_pattern: the point through the pattern's transforms and warps (Warp_EPoint), then the pattern and
// its frequency/phase/wave step (Evaluate_TPat). No colour map is looked at.
class RendererPattern final : public PreparedPattern {
 public:
  explicit RendererPattern(const Pigment& p) : pigment_(p) {}
  double value(Vec3 point, int noise_generator) const override {
    const RenderPigment& r = pigment_.with(noise_generator);
    return apply_wave(pattern_value(r.params, to_pattern_space(r, point)), r.wave);
  }

 private:
  PigmentPerGenerator pigment_;
};

// POV-Ray's f_pigment: Compute_Pigment at the point with no intersection and no ray, the same colour shading
// computes there (transforms, warps, colour and pigment maps), all five channels.
class RendererPigment final : public PreparedPigment {
 public:
  explicit RendererPigment(const Pigment& p) : pigment_(p) {}
  Colour colour(Vec3 point, int noise_generator) const override {
    const Colour c = evaluate_pigment(pigment_.with(noise_generator), point);
    // POV-Ray's colours are single precision: F(…).red of a pigment that gives 0.7 is 0.699999988.
    auto single = [](double v) { return static_cast<double>(static_cast<float>(v)); };
    return {single(c.r), single(c.g), single(c.b), single(c.f), single(c.t)};
  }

 private:
  PigmentPerGenerator pigment_;
};

// Whether the pigment or a pigment of its maps is uv_mapped: a pigment function has no surface, so no u, v.
bool uses_uv_mapping(const Pigment& p) {
  if (p.pattern == PatternKind::uv_mapping) return true;
  for (const MapEntry& e : p.entries)
    if (e.pigment && uses_uv_mapping(*e.pigment)) return true;
  return false;
}

}  // namespace

std::variant<std::shared_ptr<const PreparedPattern>, std::string> RendererPatterns::prepare(const Pigment& p) const {
  switch (p.pattern) {
    case PatternKind::solid: return std::string("a pattern function without a pattern");
    case PatternKind::average: return std::string("the pattern 'average' in a pattern function");
    case PatternKind::image_map: return std::string("the pattern 'image_map' in a pattern function");
    case PatternKind::uv_mapping: return std::string("uv_mapping in a pattern function");
    default: break;
  }
  return std::shared_ptr<const PreparedPattern>(std::make_shared<RendererPattern>(p));
}

std::variant<std::shared_ptr<const PreparedPigment>, std::string> RendererPatterns::prepare_pigment(
    const Pigment& p) const {
  if (uses_uv_mapping(p)) return std::string("uv_mapping (a pigment function has no surface, so no u, v)");
  return std::shared_ptr<const PreparedPigment>(std::make_shared<RendererPigment>(p));
}

}  // namespace povtrace::render

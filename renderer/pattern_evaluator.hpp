// The renderer's side of pattern and pigment functions (scene/pattern_evaluator.hpp): `function { pattern { … } }`
// and `function { pigment { … } }` evaluated with the renderer's own pattern code, the same that colours pigments.
#pragma once

#include <memory>
#include <string>
#include <variant>

#include "scene/pattern_evaluator.hpp"

namespace povtrace::render {

// The implementation to hand the parser in ParseOptions::pattern_evaluator: the program makes one. Stateless and
// shareable between threads.
class RendererPatterns final : public PatternEvaluator {
 public:
  std::variant<std::shared_ptr<const PreparedPattern>, std::string> prepare(const Pigment& pattern) const override;
  std::variant<std::shared_ptr<const PreparedPigment>, std::string> prepare_pigment(
      const Pigment& pigment) const override;
};

}  // namespace povtrace::render

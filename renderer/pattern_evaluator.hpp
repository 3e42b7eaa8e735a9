// The renderer's side of pattern and pigment functions (scene/pattern_evaluator.hpp): `function { pattern { … } }`
// and `function { pigment { … } }` evaluated with the renderer's own pattern code, the same that colours pigments.
#pragma once

#include <memory>

#include "scene/pattern_evaluator.hpp"

namespace povtrace::render {

// The implementation to hand the parser in ParseOptions::pattern_evaluator. Stateless and shareable.
std::shared_ptr<const PatternEvaluator> pattern_evaluator();

}  // namespace povtrace::render

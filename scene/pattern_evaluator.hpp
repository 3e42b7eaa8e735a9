// Pattern values for `function { pattern { … } }` (POV-Ray's f_pattern): the value of the pattern at a point, after
// the pattern's own transforms, warps and turbulence and its frequency/phase/wave step, before any colour map.
// Colours for `function { pigment { … } }` (POV-Ray's f_pigment): the pigment's colour at the point as shading
// computes it (transforms, warps, colour or pigment map), without an intersection, all five of r, g, b, filter,
// transmit.
// Evaluating patterns and pigments is the renderer's work, and the parser never includes renderer code: it asks
// through this interface, which the program hands it in ParseOptions::pattern_evaluator
// (renderer/pattern_evaluator.hpp implements it). Without one, a pattern or pigment function other than a plain
// colour is refused by name when it is evaluated.
#pragma once

#include <memory>
#include <string>
#include <variant>

#include "scene/description.hpp"

namespace povtrace {

// One pattern made ready for repeated evaluation (isosurfaces and height fields evaluate it many times). Shared
// by every thread that renders: value() must not change it.
class PreparedPattern {
 public:
  virtual ~PreparedPattern() = default;
  // The pattern's value at `point` (function space = the pattern's world space). `noise_generator` is the scene's
  // (1, 2 or 3), read when the function runs.
  virtual double value(Vec3 point, int noise_generator) const = 0;
};

// One pigment made ready for repeated evaluation, shared like PreparedPattern: colour() must not change it.
class PreparedPigment {
 public:
  virtual ~PreparedPigment() = default;
  // The pigment's colour at `point` (function space = the pigment's world space); `noise_generator` as above.
  virtual Colour colour(Vec3 point, int noise_generator) const = 0;
};

class PatternEvaluator {
 public:
  virtual ~PatternEvaluator() = default;
  // The pattern block parsed as a pigment (its colour map, if any, is not used). A pattern the renderer cannot
  // evaluate gives what it is called in an "unsupported" message instead (the pigment is never tainted: the
  // caller refuses tainted ones first).
  virtual std::variant<std::shared_ptr<const PreparedPattern>, std::string> prepare(const Pigment& pattern) const = 0;
  // The pigment of a pigment function, or what the renderer cannot evaluate in it (as prepare()).
  virtual std::variant<std::shared_ptr<const PreparedPigment>, std::string> prepare_pigment(
      const Pigment& pigment) const = 0;
};

}  // namespace povtrace

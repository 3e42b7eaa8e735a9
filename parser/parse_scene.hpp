// The front end's one entry point: scene file in, SceneDescription out.
//
// Stages (STYLE.md (a)): PEGTL lexer (lexer.hpp) → token stream with directives, #include and macro calls
// handled between any two tokens (interpreter, token_stream.cpp / directives.cpp) → expression evaluation and
// statement parsing into plain description structs → post-processing of textures as POV-Ray's parser does
// when an object is placed. Throws ParseError (file:line:column, source line, caret, what was expected).
#pragma once

#include <atomic>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "scene/description.hpp"
#include "scene/object_geometry.hpp"
#include "scene/pattern_evaluator.hpp"
#include "scene/source.hpp"

namespace povtrace {

struct ParseOptions {
  // Include search after the working directory (+L paths in order); the standard POV-Ray include directory
  // is appended by parse_scene when it exists and is not listed already.
  std::vector<std::filesystem::path> library_paths;
  std::vector<std::pair<std::string, double>> declares;   // Declare=NAME=VALUE
  // The animation's values for this frame (POV-Ray 3.7's front end declares them for every parse: all 0 when
  // nothing is animated). `clock` is +K's value or the frame's clock; `clock_on` is true exactly when it is set.
  std::optional<double> clock;
  struct FrameValues {
    double clock_delta = 0, final_clock = 0, final_frame = 0, frame_number = 0, initial_clock = 0, initial_frame = 0;
  } frame;
  std::vector<std::pair<std::string, std::string>> string_declares;   // Declare=NAME="text" (after the floats)
  // +HI / Include_Header: a file read as if #included before the scene's first token (found like an #include).
  std::optional<std::filesystem::path> include_header;
  // +MV / Version: the language version (round(100 · v)) the parse starts with; a #version changes it as usual.
  std::optional<int> initial_language_version;
  // +WL / Warning_Level (0-9): below 5 the parser's warnings and #warning are not reported (POV-Ray's
  // MessageFactory drops every warning below level 5).
  int warning_level = 9;
  int image_width = 800;
  int image_height = 600;
  bool output_alpha = false;
  // Receives #debug/#warning text and parser warnings (already formatted). Default: stderr.
  std::function<void(const std::string&)> message_sink;
  // When set, receives the same text with its kind instead (povtrace's +GD/+GW streams): #debug text, or a
  // warning (#warning and the parser's own).
  enum class MessageKind { debug, warning };
  std::function<void(MessageKind, const std::string&)> classified_sink;
  // Stop with a ParseError after reading this many tokens (0: no limit). POV-Ray runs a runaway #while forever,
  // and so does povtrace by default; the fuzzer (fuzz/) needs every input to end.
  std::uint64_t max_tokens = 0;
  // Ray-object geometry for trace() and for inside() of shapes the parser does not test itself; the program passes
  // the renderer's (render::object_geometry()). Null: those are refused by name.
  std::shared_ptr<const ObjectGeometry> object_geometry;
  // Pattern values for `function { pattern { … } }`; the program passes the renderer's
  // (render::pattern_evaluator()). Null: pattern functions are refused by name when they are evaluated.
  std::shared_ptr<const PatternEvaluator> pattern_evaluator;
  // --povray-tolerances: the parser's own absolute tolerances as POV-Ray applies them, which matter only for
  // scenes far below unit size (the renderer otherwise draws those as a rescaled twin, renderer/scene_scale.hpp):
  // a camera whose look_at is closer than 1e-5 to its location is an error.
  bool povray_tolerances = false;
  // Replayed expressions (loops, macro bodies) run as programs compiled from their kept tokens
  // (parser/expressions/expressions.cpp, "expression programs"): same values, warnings and errors as the full
  // parse, several times faster. Off (--no-specialise=expression-programs): every expression is read by the full
  // parse, which differential tests compare against.
  bool expression_programs = true;
  // Set from elsewhere (povtrace's Ctrl-C handler) to stop the parse with a ParseError at the token it reached:
  // a runaway #while, which POV-Ray and povtrace otherwise run forever, must still stop on Ctrl-C.
  const std::atomic<bool>* cancel = nullptr;
  // Called with each object as it joins the scene's objects, in their order, while it still holds the parser's notes
  // (Object::parser_notes, parser/extents/object_notes.hpp), which the returned scene no longer does: tests read
  // there the state of POV-Ray's box of the object, or what the parser left pending on it.
  std::function<void(const Object&)> placing;
};

inline constexpr const char* kStandardIncludeDir = "/usr/share/povray-3.7/include";

SceneDescription parse_scene(const std::filesystem::path& file, const ParseOptions& options);

// The same, from text in memory (tests); `name` is used in messages.
SceneDescription parse_scene_text(const std::string& text, const std::string& name, const ParseOptions& options);

}  // namespace povtrace

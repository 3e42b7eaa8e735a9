// Helpers shared by the parser tests: parse text in memory, collect #debug/#warning output through
// ParseOptions::message_sink, catch the ParseError of a malformed scene, and private temporary folders
// (ScratchFolder, from tests/common/scratch_folder.hpp).
#pragma once

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#include <gtest/gtest.h>

#include "parser/parse_scene.hpp"
#include "tests/common/scratch_folder.hpp"

namespace povtrace::test {

// Every message the parser sent to the sink (#debug text verbatim, warnings formatted), in order.
struct Messages {
  std::vector<std::string> items;
  std::string joined() const {
    std::string all;
    for (const auto& m : items) all += m;
    return all;
  }
};

inline ParseOptions options_into(Messages& messages) {
  ParseOptions o;
  o.message_sink = [&messages](const std::string& text) { messages.items.push_back(text); };
  return o;
}

// Parses `text` as the scene "test.pov"; messages go to `messages` (or are dropped).
inline SceneDescription parse(const std::string& text, Messages* messages = nullptr) {
  Messages ignored;
  return parse_scene_text(text, "test.pov", options_into(messages ? *messages : ignored));
}

// The concatenated #debug output of a scene.
inline std::string debug_output(const std::string& text) {
  Messages m;
  parse(text, &m);
  return m.joined();
}

// The error a malformed scene must raise; fails the test (and returns an empty error) when it parses.
inline ParseError parse_error(const std::string& text, const ParseOptions& options = {},
                              const std::string& name = "test.pov") {
  ParseOptions o = options;
  if (!o.message_sink) o.message_sink = [](const std::string&) {};
  try {
    parse_scene_text(text, name, o);
  } catch (const ParseError& e) {
    return e;
  }
  ADD_FAILURE() << "expected a ParseError for:\n" << text;
  return ParseError(SourceLoc{}, "<no error>");
}

// The float printed by `#debug concat(str(EXPR,0,9),"\n")` in a #version 3.7 scene (the last message: warnings
// about the expression come before it).
inline double eval_float(const std::string& expr, const std::string& prelude = "") {
  Messages m;
  parse("#version 3.7;\n" + prelude + "\n#debug concat(str(" + expr + ",0,9),\"\\n\")\n", &m);
  if (m.items.empty()) {
    ADD_FAILURE() << "no output for " << expr;
    return 0;
  }
  return std::strtod(m.items.back().c_str(), nullptr);
}

// The five terms printed by vstr(5, EXPR, ...), i.e. a vector or colour promoted to five terms.
inline std::vector<double> eval_terms(const std::string& expr, const std::string& prelude = "") {
  const std::string out = debug_output("#version 3.7;\n" + prelude + "\n#debug concat(vstr(5," + expr +
                                       ",\" \",0,9),\"\\n\")\n");
  std::istringstream in(out);
  std::vector<double> terms;
  double v = 0;
  while (in >> v) terms.push_back(v);
  return terms;
}

// Changes the working directory for the lifetime of the guard (#include searches it first).
class WorkingDirectory {
 public:
  explicit WorkingDirectory(const std::filesystem::path& dir) : saved_(std::filesystem::current_path()) {
    std::filesystem::current_path(dir);
  }
  ~WorkingDirectory() {
    std::error_code ignored;
    std::filesystem::current_path(saved_, ignored);
  }
  WorkingDirectory(const WorkingDirectory&) = delete;
  WorkingDirectory& operator=(const WorkingDirectory&) = delete;

 private:
  std::filesystem::path saved_;
};

}  // namespace povtrace::test

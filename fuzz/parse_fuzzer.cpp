// libFuzzer target for the SDL front end: arbitrary bytes as a scene file. A ParseError is the expected outcome
// of most inputs; any other exception (it reaches std::terminate), a crash, or an ASan/UBSan report is a finding.
// Built by scripts/fuzz.sh (clang, -DPOVTRACE_FUZZ=ON); see fuzz/CMakeLists.txt.
#include <cstddef>
#include <cstdint>
#include <string>

#include "parser/parse_scene.hpp"

namespace {
const povtrace::ParseOptions& fuzz_options() {
  static const povtrace::ParseOptions options = [] {
    povtrace::ParseOptions o;
    o.message_sink = [](const std::string&) {};   // #debug and warnings are dropped
    // A runaway #while is legal SDL (POV-Ray loops forever too): cap the work so every input ends.
    o.max_tokens = 200000;
    return o;
  }();
  return options;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    povtrace::parse_scene_text(text, "fuzz.pov", fuzz_options());
  } catch (const povtrace::ParseError&) {
    // a located error: the front end did its job
  }
  return 0;
}

#include "renderer/located_error.hpp"

namespace povtrace::render {

void fail_at_scene(const SourceLoc& at, const std::string& message) {
  std::string line;
  try {
    const std::string text = read_text_file(at.file_name());
    std::size_t begin = 0;
    for (int n = 1; n < at.line && begin != std::string::npos; ++n) {
      begin = text.find('\n', begin);
      if (begin != std::string::npos) ++begin;
    }
    if (begin != std::string::npos) line = text.substr(begin, text.find('\n', begin) - begin);
  } catch (const std::exception&) {
    // the message alone, without the line
  }
  throw ParseError(at, message, line);
}

}  // namespace povtrace::render

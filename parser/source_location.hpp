// A position in a scene source file. Small value type carried by every description entity so that errors
// found after parsing can still name file:line:column.
#pragma once

#include <memory>
#include <string>

namespace povtrace {

struct SourceLoc {
  std::shared_ptr<const std::string> file;  // shared: millions of locations must not copy the name
  int line = 0;                             // 1-based; 0 = unknown
  int column = 0;                           // 1-based, in bytes

  std::string file_name() const { return file ? *file : std::string("<unknown>"); }
  std::string to_string() const {
    return file_name() + ":" + std::to_string(line) + ":" + std::to_string(column);
  }
};

}  // namespace povtrace

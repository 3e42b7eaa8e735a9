// A position in a scene source file. Small value type carried by every description entity so that errors
// found after parsing can still name file:line:column.
#pragma once

#include <memory>
#include <string>
#include <string_view>

namespace povtrace {

// A file name interned in a process-wide pool that is never freed: copying a location copies one pointer (no
// reference count to update: every token carries a location), and equal names are the same pointer. The pool
// holds one entry per distinct file name, so it stays small.
class FileName {
 public:
  FileName() = default;
  FileName(std::nullptr_t) {}   // NOLINT: "no file", as a null shared_ptr was
  // Implicit, so that code written for the former shared_ptr member (make_shared<const std::string>(…)) keeps
  // compiling.
  FileName(const std::shared_ptr<const std::string>& name);   // NOLINT
  explicit FileName(std::string_view name) : name_(intern(name)) {}

  const std::string& operator*() const { return *name_; }
  const std::string* operator->() const { return name_; }
  const std::string* get() const { return name_; }
  explicit operator bool() const { return name_ != nullptr; }
  friend bool operator==(const FileName&, const FileName&) = default;

 private:
  static const std::string* intern(std::string_view name);
  const std::string* name_ = nullptr;
};

struct SourceLoc {
  FileName file;     // interned: millions of locations must not copy the name
  int line = 0;      // 1-based; 0 = unknown
  int column = 0;    // 1-based, in bytes

  std::string file_name() const { return file ? *file : std::string("<unknown>"); }
  std::string to_string() const {
    return file_name() + ":" + std::to_string(line) + ":" + std::to_string(column);
  }
};

}  // namespace povtrace

// A position in a scene source file. Small value type carried by every description entity so that errors
// found after parsing can still name file:line:column.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <string_view>
#include <unordered_set>
#include <vector>

namespace povtrace {

// A file name held in a FileNames pool: copying a location copies one pointer (no reference count to update:
// every token carries a location), and equal names of one pool are the same pointer. It is valid as long as its
// pool lives.
class FileName {
 public:
  FileName() = default;
  FileName(std::nullptr_t) {}   // NOLINT: "no file"

  const std::string& operator*() const { return *name_; }
  const std::string* operator->() const { return name_; }
  const std::string* get() const { return name_; }
  explicit operator bool() const { return name_ != nullptr; }
  friend bool operator==(const FileName&, const FileName&) = default;

 private:
  friend class FileNames;
  explicit FileName(const std::string* name) : name_(name) {}
  const std::string* name_ = nullptr;
};

// The file names locations point to, one entry per distinct name (so it stays small). A parse makes one and hands
// it to its SceneDescription (SceneDescription::file_names), so the locations of what the parse made stay valid
// as long as the description does; a ParseError keeps a pool of its own for its one name.
class FileNames {
 public:
  FileName intern(std::string_view name) { return FileName(&*names_.emplace(name).first); }
  // Every name of the pool, sorted: the files a parse read (the scene, its #include files, …).
  std::vector<std::string> all() const {
    std::vector<std::string> names(names_.begin(), names_.end());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  std::unordered_set<std::string> names_;   // node-based: a name never moves
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

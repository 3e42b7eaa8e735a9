// The symbol-table stack (§3): [0] globals, then one table per open include file and per active macro call.
// Lookup runs newest to oldest (dynamic scope).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "parser/values.hpp"

namespace povtrace::sdl {

class SymbolTable {
 public:
  SymbolTable() : tables_(1), deprecations_(1) {}

  void push_scope() { tables_.emplace_back(); deprecations_.emplace_back(); }
  void pop_scope() { tables_.pop_back(); deprecations_.pop_back(); }
  std::size_t depth() const { return tables_.size(); }

  // The value visible under `name`, following macro aliases; nullptr if undeclared. Takes the token's text as it
  // is: no string is made for a lookup.
  const Value* find(std::string_view name) const;
  // Level of the innermost table that holds `name` (aliases not followed).
  std::optional<std::size_t> level_of(std::string_view name) const;

  // #declare: overwrite the visible entry wherever it is (through aliases), else create a global.
  void declare(const std::string& name, Value value);
  // #local: overwrite in the innermost table (through an alias there), else create there.
  void local(const std::string& name, Value value);
  // Binds a name in the innermost table without following aliases (macro parameters, #for variables).
  void bind(const std::string& name, Value value) { tables_.back()[name] = std::move(value); }
  // #undef: removes the innermost visible entry; false if there was none.
  bool undefine(const std::string& name);

  // `#declare deprecated [once] "message" Name = …` (§4): marks the entry now visible under `name`. Reading
  // it later warns with the message (only the first time with `once`). The mark stays with the entry when it is
  // assigned again, as in POV-Ray.
  struct Deprecation {
    std::string message;
    bool once = false;
    bool shown = false;
  };
  void deprecate(const std::string& name, Deprecation d);
  // The deprecation of the entry visible under `name`, if any (cheap while nothing was ever deprecated).
  Deprecation* deprecation(const std::string& name);
  bool any_deprecated() const { return any_deprecated_; }

 private:
  Value* resolve_alias(Value* v);
  // Hashes a std::string and a std::string_view alike, so that lookups by string_view need no std::string.
  struct NameHash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const noexcept {   // FNV-1a, inline: names are short
      std::uint64_t h = 14695981039346656037ull;
      for (const char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
      return static_cast<std::size_t>(h ^ (h >> 32));
    }
  };
  std::vector<std::unordered_map<std::string, Value, NameHash, std::equal_to<>>> tables_;
  std::vector<std::unordered_map<std::string, Deprecation>> deprecations_;   // parallel to tables_
  bool any_deprecated_ = false;
};

}  // namespace povtrace::sdl

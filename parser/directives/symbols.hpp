// The symbol-table stack (§3): [0] globals, then one table per open include file and per active macro call.
// Lookup runs newest to oldest (dynamic scope).
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "parser/expressions/values.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

class SymbolTable {
 public:
  // Every identifier gets a small number when its token is first lexed (NameId, 0 = none), so that a lookup
  // indexes an array instead of hashing and comparing text: loops and macros read the same names millions of
  // times. Whether the name is a reserved word is decided once, at interning.
  using NameId = std::uint32_t;
  NameId intern(std::string_view name);
  // The two halves of intern() for a run of names (the lexer's): the name's hash, its slot in the table asked
  // for from memory; then the interning with that hash. The slots of a large scene's names are scattered over
  // megabytes, so the misses of a run overlap instead of coming one after the other.
  std::uint64_t prefetch(std::string_view name) const;
  NameId intern(std::string_view name, std::uint64_t hash);
  NameId id_of(std::string_view name) const;   // 0 if never interned (then nothing is bound to it)
  bool is_reserved(NameId id) const { return reserved_[id] != 0; }

  SymbolTable();
  // The tables of levels left are kept (emptied) for the next push: a macro call must not allocate its table.
  void push_scope() {
    if (depth_ == scopes_.size()) {
      scopes_.emplace_back();
      deprecations_.emplace_back();
    }
    ++depth_;
  }
  void pop_scope();
  std::size_t depth() const { return depth_; }

  // The value visible under `name`, following macro aliases; nullptr if undeclared. Takes the token's text as it
  // is: no string is made for a lookup.
  // Inline, with the alias chain out of line: loops and macros look names up millions of times.
  const Value* find(NameId id) const {
    const Entry* e = top(id);
    if (!e) return nullptr;
    Value* v = const_cast<Value*>(&e->value);
    return std::holds_alternative<Alias>(*v) ? resolve_alias(v) : v;
  }
  const Value* find(std::string_view name) const { return find(id_of(name)); }
  // Level of the innermost table that holds `name` (aliases not followed).
  std::optional<std::size_t> level_of(NameId id) const;
  std::optional<std::size_t> level_of(std::string_view name) const { return level_of(id_of(name)); }

  // #declare: overwrite the visible entry wherever it is (through aliases), else create a global.
  void declare(NameId id, Value value);
  void declare(const std::string& name, Value value) { declare(intern(name), std::move(value)); }
  // #local: overwrite in the innermost table (through an alias there), else create there.
  void local(NameId id, Value value);
  void local(const std::string& name, Value value) { local(intern(name), std::move(value)); }
  // The assignment of a #declare or #local whose target table was chosen before its value was parsed (POV-Ray's
  // Parse_Declare adds the symbol first, so `#local R = M()` inside a macro assigns the caller's table even when
  // M's body ends the value before M's #end): overwrite the name's entry in table `level` (through an alias),
  // else create it there. A level that no longer exists falls back to local().
  void assign_at(NameId id, std::size_t level, Value value);
  // assign_at() of a number: where the entry it assigns holds a number, that number is overwritten in place.
  void assign_numeric_at(NameId id, std::size_t level, const Numeric& n);
  // Binds a name in the innermost table without following aliases (macro parameters, #for variables).
  void bind(NameId id, Value value);
  void bind(const std::string& name, Value value) { bind(intern(name), std::move(value)); }
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
  struct Entry {
    std::size_t level = 0;
    Value value;
    Entry* below = nullptr;   // the same name's entry in the next outer level that holds it
  };
  Entry* top(NameId id) const { return id < bindings_.size() ? bindings_[id] : nullptr; }
  Value* resolve_alias(Value* v) const;
  void add_entry(NameId id, std::size_t level, Value value);
  static std::uint64_t hash(std::string_view s) {   // FNV-1a: names are short
    std::uint64_t h = 14695981039346656037ull;
    for (const char c : s) h = (h ^ static_cast<unsigned char>(c)) * 1099511628211ull;
    return h;
  }
  // The slot of `name` in ids_: the one holding its id, or the empty one where it would go.
  std::size_t slot_of(std::string_view name, std::uint64_t h) const;
  std::vector<std::string> names_;       // by id
  std::vector<std::uint64_t> hashes_;    // by id
  // Open addressing on the hash, linear probing, a power of 2 in size; id 0 = empty. Each slot keeps the upper half
  // of its name's hash, so that a probe compares text only where the hashes agree: the first reading of a scene
  // of 100,000 names missed the cache on hashes_ and names_ at every probe (a fifth of its parse).
  struct Slot {
    NameId id = 0;
    std::uint32_t tag = 0;
  };
  static std::uint32_t tag_of(std::uint64_t h) { return static_cast<std::uint32_t>(h >> 32); }
  std::vector<Slot> ids_;
  std::vector<std::uint8_t> reserved_;   // by id
  // Shallow binding: for each name, the entry of the innermost level that holds it (the visible one), the outer
  // ones chained below it (levels decrease along the chain). A chain, not a vector per name: a scene declaring
  // 100,000 names made and freed 100,000 vectors. Entries live in a deque (stable addresses: callers keep
  // `const Value*` while other names are bound) and are recycled through free_.
  std::vector<Entry*> bindings_;                // by id
  std::vector<std::vector<NameId>> scopes_;     // by level: the names bound there, to unbind at pop_scope
  std::size_t depth_ = 1;                       // levels in use (scopes_ may hold more, empty, for reuse)
  std::deque<Entry> entries_;
  std::vector<Entry*> free_;
  std::vector<std::unordered_map<std::string, Deprecation>> deprecations_;   // by level
  bool any_deprecated_ = false;
};

// Whether the token is a reserved word: by its NameId where it has one.
inline bool reserved(const SymbolTable& symbols, const Token& t) {
  return t.name ? symbols.is_reserved(t.name) : is_reserved_word(t.text);
}
// The value an identifier token stands for: an array element's value (Token::element), else the symbol visible
// under its name; nullptr for anything else.
inline const Value* lookup(const SymbolTable& symbols, const Token& t) {
  if (t.element) return &t.element->value;
  if (t.kind != TokenKind::identifier || reserved(symbols, t)) return nullptr;
  return t.name ? symbols.find(t.name) : symbols.find(t.text);
}

}  // namespace povtrace::sdl

#include "parser/directives/symbols.hpp"

#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
struct Namer {
  template <class T> std::string operator()(const Boxed<T>& b) const { return (*this)(*b); }
  std::string operator()(const Numeric& n) const {
    if (n.colour) return "colour";
    static const char* names[] = {"", "float", "2-D vector", "vector", "4-D vector", "colour"};
    return names[n.terms];
  }
  std::string operator()(const std::string&) const { return "string"; }
  std::string operator()(const std::shared_ptr<const SceneItem>& s) const {
    return std::holds_alternative<Light>(*s) ? "light_source" : "object";
  }
  std::string operator()(const std::shared_ptr<const Texture>&) const { return "texture"; }
  std::string operator()(const Pigment&) const { return "pigment"; }
  std::string operator()(const Finish&) const { return "finish"; }
  std::string operator()(const Interior&) const { return "interior"; }
  std::string operator()(const Camera&) const { return "camera"; }
  std::string operator()(const MacroDefinition&) const { return "macro"; }
  std::string operator()(const Alias&) const { return "alias"; }
  std::string operator()(const Matrix&) const { return "transform"; }
  std::string operator()(const OpaqueValue& o) const { return o.keyword; }
  std::string operator()(const MaterialValue&) const { return "material"; }
  std::string operator()(const std::shared_ptr<ArrayValue>&) const { return "array"; }
  std::string operator()(const std::shared_ptr<UserFile>&) const { return "file"; }
  std::string operator()(const std::shared_ptr<const FunctionValue>&) const { return "function"; }
  std::string operator()(const SkySphere&) const { return "sky_sphere"; }
  std::string operator()(const BlendMapValue& m) const {
    return m.textures ? "texture_map" : m.pigments ? "pigment_map" : m.densities ? "density_map" : "color_map";
  }
  std::string operator()(const Normal&) const { return "normal"; }
  std::string operator()(const SplineValue&) const { return "spline"; }
  std::string operator()(const Media&) const { return "media"; }
  std::string operator()(const DensityValue&) const { return "density"; }
};
}  // namespace

std::string value_type_name(const Value& v) { return std::visit(Namer{}, v); }

std::string array_type_of(const Value& v) {
  if (const auto* n = std::get_if<Numeric>(&v)) {
    static const char* names[] = {"", "float", "2-D vector", "vector", "4-D vector", "colour"};
    return n->colour ? "colour" : names[n->terms];
  }
  if (std::holds_alternative<std::shared_ptr<const SceneItem>>(v)) return "object";
  return value_type_name(v);
}

std::shared_ptr<ArrayValue> ArrayValue::deep_copy() const {
  auto copy = std::make_shared<ArrayValue>(*this);
  for (auto& e : copy->elements)
    if (e)
      if (auto* inner = std::get_if<std::shared_ptr<ArrayValue>>(&*e)) *inner = (*inner)->deep_copy();
  return copy;
}

SymbolTable::SymbolTable()
    : names_(1), hashes_(1, 0), ids_(1024), reserved_(1, 0), bindings_(1), scopes_(1), deprecations_(1) {}

std::size_t SymbolTable::slot_of(std::string_view name, std::uint64_t h) const {
  const std::size_t mask = ids_.size() - 1;
  const std::uint32_t tag = tag_of(h);
  for (std::size_t i = static_cast<std::size_t>(h ^ (h >> 29)) & mask;; i = (i + 1) & mask) {
    const Slot& slot = ids_[i];
    if (slot.id == 0 || (slot.tag == tag && names_[slot.id] == name)) return i;
  }
}

std::uint64_t SymbolTable::prefetch(std::string_view name) const {
  const std::uint64_t h = hash(name);
  __builtin_prefetch(&ids_[static_cast<std::size_t>(h ^ (h >> 29)) & (ids_.size() - 1)]);
  return h;
}

SymbolTable::NameId SymbolTable::intern(std::string_view name) { return intern(name, hash(name)); }

SymbolTable::NameId SymbolTable::intern(std::string_view name, std::uint64_t h) {
  std::size_t slot = slot_of(name, h);
  if (ids_[slot].id != 0) return ids_[slot].id;
  const auto id = static_cast<NameId>(names_.size());
  names_.emplace_back(name);
  hashes_.push_back(h);
  reserved_.push_back(is_reserved_word(name) ? 1 : 0);
  bindings_.push_back(nullptr);
  if (2 * names_.size() > ids_.size()) {   // at most half full: probes stay short
    ids_.assign(ids_.size() * 2, Slot{});
    // The names are distinct: each goes to the first empty slot of its probe, no text compared.
    const std::size_t mask = ids_.size() - 1;
    for (NameId k = 1; k < id; ++k) {
      std::size_t i = static_cast<std::size_t>(hashes_[k] ^ (hashes_[k] >> 29)) & mask;
      while (ids_[i].id != 0) i = (i + 1) & mask;
      ids_[i] = Slot{k, tag_of(hashes_[k])};
    }
    slot = slot_of(name, h);
  }
  ids_[slot] = Slot{id, tag_of(h)};
  return id;
}

SymbolTable::NameId SymbolTable::id_of(std::string_view name) const { return ids_[slot_of(name, hash(name))].id; }

void SymbolTable::pop_scope() {
  const std::size_t level = depth_ - 1;
  for (const NameId id : scopes_[level]) {
    Entry* e = bindings_[id];
    // #undef may have removed the entry already (a name is listed again when it is bound again).
    if (!e || e->level != level) continue;
    bindings_[id] = e->below;
    e->value = Numeric{};   // release what it held now, not when the entry is reused
    free_.push_back(e);
  }
  scopes_[level].clear();
  deprecations_[level].clear();
  --depth_;
}

void SymbolTable::add_entry(NameId id, std::size_t level, Value value) {
  Entry* e = nullptr;
  if (free_.empty()) {
    e = &entries_.emplace_back();
  } else {
    e = free_.back();
    free_.pop_back();
  }
  e->level = level;
  e->value = std::move(value);
  // Levels decrease along a name's chain. A new entry is usually made in the innermost level, or global; an
  // assignment whose target was fixed before a macro call in its value ran (assign_at) may add one below entries
  // of deeper levels.
  Entry** at = &bindings_[id];
  while (*at && (*at)->level > level) at = &(*at)->below;
  e->below = *at;
  *at = e;
  scopes_[level].push_back(id);
}

std::optional<std::size_t> SymbolTable::level_of(NameId id) const {
  if (const Entry* e = top(id)) return e->level;
  return std::nullopt;
}

Value* SymbolTable::resolve_alias(Value* v) const {
  // Alias chains are finite: an alias always points to an outer (older) table.
  while (v && std::holds_alternative<Alias>(*v)) {
    const Alias& a = std::get<Alias>(*v);
    const NameId id = a.id;
    v = nullptr;
    for (Entry* e = top(id); e; e = e->below)
      if (e->level == a.table) {
        v = &e->value;
        break;
      }
  }
  return v;
}

void SymbolTable::declare(NameId id, Value value) {
  if (Entry* e = top(id)) {
    if (Value* target = resolve_alias(&e->value)) *target = std::move(value);
    else e->value = std::move(value);
    return;
  }
  add_entry(id, 0, std::move(value));
}

void SymbolTable::local(NameId id, Value value) {
  Entry* e = top(id);
  if (e && e->level == depth() - 1) {
    if (Value* target = resolve_alias(&e->value)) *target = std::move(value);
    else e->value = std::move(value);
    return;
  }
  add_entry(id, depth() - 1, std::move(value));
}

void SymbolTable::assign_at(NameId id, std::size_t level, Value value) {
  if (level >= depth()) return local(id, std::move(value));
  for (Entry* e = top(id); e; e = e->below)
    if (e->level == level) {
      if (Value* target = resolve_alias(&e->value)) *target = std::move(value);
      else e->value = std::move(value);
      return;
    }
  add_entry(id, level, std::move(value));
}

void SymbolTable::assign_numeric_at(NameId id, std::size_t level, const Numeric& n) {
  if (level < depth())
    for (Entry* e = top(id); e; e = e->below)
      if (e->level == level) {
        // assign_at's target: through the alias, or the entry itself where the alias leads nowhere.
        Value* target = resolve_alias(&e->value);
        if (!target) target = &e->value;
        if (auto* old = std::get_if<Numeric>(target)) *old = n;
        else *target = n;
        return;
      }
  assign_at(id, level, Value(n));
}

void SymbolTable::bind(NameId id, Value value) {
  Entry* e = top(id);
  if (e && e->level == depth() - 1) e->value = std::move(value);
  else add_entry(id, depth() - 1, std::move(value));
}

bool SymbolTable::undefine(const std::string& name) {
  const NameId id = id_of(name);
  Entry* e = top(id);
  if (!e) return false;
  deprecations_[e->level].erase(name);
  bindings_[id] = e->below;
  e->value = Numeric{};
  free_.push_back(e);
  return true;
}

void SymbolTable::deprecate(const std::string& name, Deprecation d) {
  auto level = level_of(name);
  if (!level) return;
  deprecations_[*level][name] = std::move(d);
  any_deprecated_ = true;
}

SymbolTable::Deprecation* SymbolTable::deprecation(const std::string& name) {
  if (!any_deprecated_) return nullptr;
  auto level = level_of(name);
  if (!level) return nullptr;
  auto it = deprecations_[*level].find(name);
  return it == deprecations_[*level].end() ? nullptr : &it->second;
}

}  // namespace povtrace::sdl

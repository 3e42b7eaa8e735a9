#include "parser/symbols.hpp"

namespace povtrace::sdl {

std::string value_type_name(const Value& v) {
  struct Namer {
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
    std::string operator()(const BlendMapValue& m) const { return m.pigments ? "pigment_map" : "color_map"; }
  };
  return std::visit(Namer{}, v);
}

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

std::optional<std::size_t> SymbolTable::level_of(std::string_view name) const {
  for (std::size_t i = tables_.size(); i-- > 0;)
    if (tables_[i].find(name) != tables_[i].end()) return i;
  return std::nullopt;
}

Value* SymbolTable::resolve_alias(Value* v) {
  // Alias chains are finite: an alias always points to an outer (older) table.
  while (v && std::holds_alternative<Alias>(*v)) {
    const Alias& a = std::get<Alias>(*v);
    auto it = tables_[a.table].find(a.name);
    v = it == tables_[a.table].end() ? nullptr : &it->second;
  }
  return v;
}

const Value* SymbolTable::find(std::string_view name) const {
  // One hash lookup per level, innermost first (not a search for the level and then another for the entry).
  auto* self = const_cast<SymbolTable*>(this);
  for (std::size_t i = tables_.size(); i-- > 0;) {
    auto& table = self->tables_[i];
    if (auto it = table.find(name); it != table.end()) return self->resolve_alias(&it->second);
  }
  return nullptr;
}

void SymbolTable::declare(const std::string& name, Value value) {
  if (auto level = level_of(name)) {
    Value& slot = tables_[*level][name];
    if (Value* target = resolve_alias(&slot)) { *target = std::move(value); return; }
    slot = std::move(value);
    return;
  }
  tables_.front()[name] = std::move(value);
}

void SymbolTable::local(const std::string& name, Value value) {
  auto& table = tables_.back();
  auto it = table.find(name);
  if (it != table.end()) {
    if (Value* target = resolve_alias(&it->second)) { *target = std::move(value); return; }
  }
  table[name] = std::move(value);
}

bool SymbolTable::undefine(const std::string& name) {
  auto level = level_of(name);
  if (!level) return false;
  tables_[*level].erase(name);
  deprecations_[*level].erase(name);
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

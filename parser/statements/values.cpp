// Right-hand values (the ValueReader part, value_reader.hpp): what #declare, #local, array initialisers and macro
// arguments read after their '=' — a number, string, texture, object, function… (POV-Ray's Parse_RValue).
#include "parser/expressions/array_values.hpp"
#include "parser/expressions/expression_parser.hpp"
#include "parser/expressions/function_values.hpp"
#include "parser/expressions/spline_values.hpp"
#include "parser/interpreter.hpp"
#include "parser/lexing/reserved_words.hpp"
#include "parser/objects/object_parser.hpp"
#include "parser/statements/camera_light_parser.hpp"
#include "parser/statements/value_reader.hpp"
#include "parser/textures/texture_parser.hpp"

namespace povtrace::sdl {

bool ValueReader::numeric_ahead() {
  const LexedToken* k = plain_ahead();
  if (!k) return false;
  if (k->kind() == TokenKind::number || k->kind() == TokenKind::symbol) return true;
  if (k->kind() != TokenKind::identifier || symbol_table().is_reserved(k->payload)) return false;
  const Value* v = symbol_table().find(k->payload);
  return v && std::holds_alternative<Numeric>(*v) && text_of(*k) != "lemon";
}

void ValueReader::call_macros_ahead() {
  // The conditions of plain_ahead(), under which next() takes the same steps: no token pushed back, no token
  // limit (next() counts), no deprecated names (their warnings come from next()).
  while (!token_stream().has_pushed_back() && !options_.max_tokens && !symbol_table().any_deprecated()) {
    const Frame& f = token_stream().frame();
    const LexedToken& k = lexed(*f.tokens, f.index);
    if (k.kind() != TokenKind::identifier || symbol_table().is_reserved(k.payload)) return;
    const Value* v = symbol_table().find(k.payload);
    if (!v || !std::holds_alternative<Boxed<MacroDefinition>>(*v)) return;
    const Token name = raw();   // what next() reads first, with the cancel check counted
    const NestingGuard guard(*this, name);
    directives_.call_macro(name);
  }
}

std::optional<Value> ValueReader::try_parse_rvalue(const Token& first) {
  // The common values first: a number, an operator or parenthesis, or a numeric identifier start an expression,
  // and none of the forms below would take them.
  if (first.kind == TokenKind::number || first.kind == TokenKind::symbol) {
    unget(first);
    return Value(expressions_.parse_additive().stored());
  }
  // ('lemon' is no reserved word in 3.7, yet try_parse_item takes it as a shape.)
  if (first.kind == TokenKind::identifier && (first.element || !reserved(first)) && first.text != "lemon")
    if (const Value* v = lookup(first); v && std::holds_alternative<Numeric>(*v)) {
      unget(first);
      return Value(expressions_.parse_additive().stored());
    }
  if (expressions_.starts_string(first)) {
    unget(first);
    return expressions_.parse_string();
  }
  const std::string_view k = first.kind == TokenKind::identifier ? first.text : std::string_view();
  if (k == "texture") {
    auto tex = textures_.parse_texture_block(first);
    // Several texture blocks in a row declare a layered texture.
    while (peek_raw().is("texture")) {   // raw: a following directive runs after this #declare
      Token more = next();
      auto top = textures_.parse_texture_block(more);
      textures_.refuse_layering(more, tex.get(), top->patterned());
      auto layered = std::make_shared<Texture>(*tex);
      for (const auto& l : top->layers) layered->layers.push_back(l);
      tex = std::move(layered);
    }
    return Value(tex);
  }
  if (k == "pigment") return Value(textures_.parse_pigment_block(first, default_texture().layers.back().pigment));
  if (k == "finish") return Value(textures_.parse_finish_block(first, default_texture().layers.back().finish));
  if (k == "normal") return Value(textures_.parse_normal_block(first, textures_.starting_normal(nullptr)));
  if (k == "color_map" || k == "colour_map" || k == "pigment_map") return Value(textures_.parse_blend_map(first));
  if (k == "texture_map") return Value(textures_.parse_texture_map(first, false));
  if (k == "interior") return Value(textures_.parse_interior_block(first, Interior{}));
  if (k == "media") return Value(textures_.parse_media_block(first));
  if (k == "density") return Value(DensityValue{textures_.parse_density_block(first)});
  if (k == "density_map") return Value(textures_.parse_density_map(first));
  if (k == "camera") return Value(camera_lights_.parse_camera(first));
  if (k == "sky_sphere") return Value(textures_.parse_sky_sphere(first));
  if (k == "transform") return Value(textures_.parse_transform_block(first));
  if (k == "material") {
    Object holder;
    objects_.parse_material_block(first, holder);
    if (holder.unsupported) return Value(OpaqueValue{"material", *holder.unsupported});
    return Value(MaterialValue{holder.texture, holder.interior_texture, holder.interior});
  }
  if (k == "array") return arrays_.parse_array_declaration(first);
  if (auto s = splines_.try_parse_rvalue(first)) return s;     // spline { … }, or a call S(…) in an expression
  if (auto f = functions_.try_parse_rvalue(first)) return f;   // function { … }, or a call F(…) in an expression
  if (const Value* v = lookup(first);
      v && !std::holds_alternative<Numeric>(*v) && !std::holds_alternative<Boxed<MacroDefinition>>(*v)) {
    if (const auto* a = std::get_if<std::shared_ptr<ArrayValue>>(v)) return Value((*a)->deep_copy());  // a value
    return *v;
  }
  if (auto item = objects_.try_parse_item(first)) return Value(std::make_shared<const SceneItem>(std::move(*item)));
  // Any other block value (color_map, normal, media, fog, sky_sphere, …): parsed
  // structurally and kept as an opaque value that is refused by name if it ever reaches the scene.
  if (first.kind == TokenKind::identifier && is_reserved_word(k) && !expressions_.starts_colour(first)) {
    Token after = peek_raw();
    if (after.is("{") || after.is("[") || (after.is("(") && (k == "function" || k == "spline"))) {
      UnsupportedFeature feature{"'" + std::string(k) + "'", first.loc};
      while (true) {   // raw look: a directive after the value runs only once it is stored (§1 item 6)
        if (Token g = peek_raw(); !(g.is("{") || g.is("[") || g.is("("))) break;
        skip_balanced(next());
      }
      return Value(OpaqueValue{std::string(k), feature});
    }
  }
  if (first.kind == TokenKind::identifier && is_reserved_word(k) && !expressions_.starts_colour(first)) {
    static const std::string_view value_words[] = {"x", "y", "z", "t", "u", "v", "pi", "true", "false", "yes",
                                                   "no", "on", "off", "version", "clock", "clock_on",
                                                   "clock_delta", "now"};
    bool is_value_word = false;
    for (auto w : value_words) is_value_word = is_value_word || k == w;
    Token after = peek();
    if (!is_value_word && !after.is("(")) return std::nullopt;
  }
  unget(first);
  return Value(expressions_.parse_additive().stored());
}

}  // namespace povtrace::sdl

// Patterned textures (povray-sdl-and-geometry.md §11). Facts from POV-Ray 3.7's parser (source/backend/parser/
// parstxtr.cpp Parse_Texture, Parse_Tiles, Parse_Pattern with TEXTURE_TYPE; express.cpp Parse_Blend_List,
// Parse_Blend_Map; parse.cpp Link_Textures; 3.7-stable):
// - A texture block without a texture identifier whose first item is no pigment, normal, finish or transform is a
//   pattern: any pattern with `texture_map { [v TEXTURE_BODY | T_id] … }` (at least one entry, at most 256; values
//   in single precision; `average` weights may be left out, 1), or checker/hexagon/brick followed by up to 2/3/2
//   `texture { … }` entries (commas optional; missing ones are the #default texture), or `tiles { texture {…}…
//   tile2 texture {…}… }` (a checker whose first entry is the tile2 texture), or `uv_mapping TEXTURE_BODY` (the
//   rest of the block is one texture, evaluated at the hit's <u, v, 0>). Without a texture_map a (non-list)
//   pattern is an error.
// - After the pattern come its modifiers (frequency, phase, waves, turbulence, warps, pattern parameters) and
//   transforms, which move the pattern only: the textures are evaluated in its space.
// - A declared patterned texture takes transforms only. Nothing is layered over a patterned texture, and it is
//   layered over nothing (objects.cpp).
// - `material_map { image … texture { } … }`: see parse_material_map.
#include "parser/interpreter.hpp"
#include "parser/textures/texture_parser.hpp"
#include "parser/lexing/reserved_words.hpp"

namespace povtrace::sdl {

namespace {
double single(double d) { return static_cast<double>(static_cast<float>(d)); }

bool is_list_pattern(PatternKind k) {
  return k == PatternKind::checker || k == PatternKind::hexagon || k == PatternKind::brick ||
         k == PatternKind::object;
}

constexpr std::size_t kMaxMapEntries = 256;   // POV-Ray's MAX_BLEND_MAP_ENTRIES
}  // namespace

bool TextureParser::starts_texture_pattern(const Token& t) {
  if (t.kind != TokenKind::identifier || !is_reserved_word(t.text)) return false;
  if (t.is("uv_mapping") || t.is("tiles") || t.is("material_map") || t.is("image_map")) return true;
  static const std::string_view patterns[] = {
      "checker", "hexagon", "brick", "gradient", "radial", "onion", "planar", "boxed", "spherical", "cylindrical",
      "leopard", "bozo", "spotted", "granite", "marble", "wood", "agate", "crackle", "cells", "average", "function", "spiral1", "spiral2", "quilted",
      "mandel", "julia", "magnet", "slope", "aoi", "pigment_pattern", "bumps", "dents", "wrinkles", "ripples", "waves", "density_file",
      "object", "image_pattern"};
  for (auto p : patterns)
    if (t.is(p)) return true;
  return false;
}

// The rest of a texture block after a declared patterned texture: transforms only (Parse_Texture_Transform).
std::shared_ptr<const Texture> TextureParser::transformed_patterned_texture(const Texture& declared, Token t,
                                                                          std::string_view closer) {
  auto tex = std::make_shared<const Texture>(declared);
  for (; !t.is(closer); t = next()) {
    Matrix m;
    if (!try_transform(t, m))
      fail_expected(t, "a transform or '" + std::string(closer) + "' after a patterned texture identifier");
    tex = transformed_texture(*tex, m);
  }
  return tex;
}

// `texture { … }` entries of checker, hexagon and brick, with the #default texture for the missing ones.
std::vector<TextureMapEntry> TextureParser::parse_texture_list(std::size_t count) {
  std::vector<TextureMapEntry> entries;
  while (entries.size() < count && peek().is("texture")) {
    const Token keyword = next();
    entries.push_back({static_cast<double>(entries.size()), parse_texture_block(keyword)});
    accept(",");
  }
  while (entries.size() < count)
    entries.push_back({static_cast<double>(entries.size()), std::make_shared<const Texture>(default_texture())});
  return entries;
}

// texture_map { [v TEXTURE_BODY] … } or texture_map { TM_id }.
BlendMapValue TextureParser::parse_texture_map(const Token& keyword, bool weights_optional) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'texture_map'");
  BlendMapValue map;
  map.textures = true;
  Token t = next();
  if (const Value* v = lookup(t); v && std::holds_alternative<BlendMapValue>(*v)) {
    map = std::get<BlendMapValue>(*v);
    if (!map.textures) fail_at(t, "this identifier is a " + value_type_name(*v) + ", not a texture_map");
    expect("}", " after the map identifier");
    return map;
  }
  for (; !t.is("}"); t = next()) {
    if (!t.is("[")) fail_expected(t, "'[' starting a texture_map entry, or '}'");
    if (map.texture_entries.size() >= kMaxMapEntries)
      fail_at(t, "too many entries in the map: POV-Ray allows at most 256");
    TextureMapEntry e;
    e.value = single(weights_optional ? optional_float(1.0) : parse_float());
    accept(",");
    e.texture = parse_texture_contents(t.loc, "]");
    map.texture_entries.push_back(std::move(e));
  }
  if (map.texture_entries.empty()) fail_at(keyword, "a map needs at least one entry");
  return map;
}

// tiles { texture {…}… tile2 texture {…}… }: a checker of two (possibly layered) textures, the first written
// entry odd, the second even (Parse_Tiles).
std::vector<TextureMapEntry> TextureParser::parse_tiles(const Token& keyword) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'tiles'");
  auto layered = [&]() {
    std::shared_ptr<const Texture> tex;
    while (peek().is("texture")) {
      const Token t = next();
      auto top = parse_texture_block(t);
      refuse_layering(t, tex.get(), top->patterned());
      if (tex) {
        auto both = std::make_shared<Texture>(*tex);
        for (const auto& l : top->layers) both->layers.push_back(l);
        top = std::move(both);
      }
      tex = std::move(top);
    }
    return tex;
  };
  auto odd = layered();
  if (!odd) fail_at(keyword, "first texture missing from tiles (as in POV-Ray)");
  expect("tile2", " in tiles { } (the second tile's textures follow it)");
  auto even = layered();
  expect("}", " closing tiles { }");
  if (!even) even = std::make_shared<const Texture>(default_texture());
  return {{0.0, even}, {1.0, odd}};
}

// A patterned texture from its first token `first` up to `closer`.
std::shared_ptr<const Texture> TextureParser::parse_patterned_texture(const Token& first, const SourceLoc& loc,
                                                                    std::string_view closer) {
  Texture tex;
  tex.loc = loc;
  auto pattern = std::make_shared<TexturePattern>();
  Pigment& carrier = pattern->pattern;
  carrier.loc = first.loc;
  if (first.is("material_map")) {
    parse_material_map(first, *pattern);
    parse_texture_pattern_modifiers(first, *pattern, closer);
    taint(tex.unsupported, carrier.unsupported);
    for (const auto& e : pattern->entries) taint(tex.unsupported, e.texture->unsupported);
    tex.pattern = std::move(pattern);
    return std::make_shared<const Texture>(std::move(tex));
  }
  if (first.is("image_map")) fail_at(first, "image_map can only be used in a pigment (as in POV-Ray)");
  if (first.is("uv_mapping")) {
    const NestingGuard guard(*this, first);   // `uv_mapping uv_mapping …` nests
    carrier.pattern = PatternKind::uv_mapping;
    pattern->entries = {{0.0, parse_texture_contents(loc, closer)}};
    taint(tex.unsupported, pattern->entries.front().texture->unsupported);
    tex.pattern = std::move(pattern);
    return std::make_shared<const Texture>(std::move(tex));
  }
  if (first.is("tiles")) {
    carrier.pattern = PatternKind::checker;
    carrier.frequency = 0.0;
    pattern->entries = parse_tiles(first);
  } else if (is_list_pattern_word(first)) {
    set_list_pattern(first, carrier);
    pattern->entries = parse_texture_list(carrier.pattern == PatternKind::hexagon ? 3 : 2);
  } else if (first.is("object")) {   // object { OBJECT [texture { } texture { }] }
    const NestingGuard guard(*this, first);
    expect("{", " after 'object' (the object pattern)");
    carrier.object = parse_pattern_object();
    taint(carrier.unsupported, carrier.object->unsupported);
    carrier.pattern = PatternKind::object;
    carrier.frequency = 0.0;
    pattern->entries = parse_texture_list(2);
    expect("}", " closing the object pattern");
  } else if (!first.is("material_map") && !try_pattern(first, carrier)) {
    fail_expected(first, "a pattern in the patterned texture");
  }
  parse_texture_pattern_modifiers(first, *pattern, closer);
  if (!is_list_pattern(carrier.pattern) && pattern->entries.empty() && !tex.unsupported && !carrier.unsupported)
    fail_at(first, "patterned texture must have texture_map (as in POV-Ray)");
  taint(tex.unsupported, carrier.unsupported);
  for (const auto& e : pattern->entries) taint(tex.unsupported, e.texture->unsupported);
  tex.pattern = std::move(pattern);
  return std::make_shared<const Texture>(std::move(tex));
}

// material_map { [type] "file" [gamma …] [once] [interpolate N] [map_type N] [repeat <u, v>] [offset <u, v>]
// texture { … } … } (POV-Ray's Parse_Material_Map): the image's palette index, or its red · 255 for an image
// without a palette, picks the texture (renderer: PatternKind::material_map). The image is read as raw values
// unless `gamma` is given (GammaCorrect off, as for bump maps). POV-Ray checks neither interpolate nor map_type
// here. At least one texture.
void TextureParser::parse_material_map(const Token& keyword, TexturePattern& pattern) {
  const NestingGuard guard(*this, keyword);
  expect("{", " after 'material_map'");
  Pigment& carrier = pattern.pattern;
  carrier.pattern = PatternKind::material_map;
  carrier.frequency = 0.0;   // the index is no wave value
  auto image = std::make_shared<ImageMap>();
  parse_image_file(keyword, *image, carrier.unsupported);
  image->gamma.mode = ImageGammaMode::none;   // Parse_Image's GammaCorrect off, as for bump maps
  image->gamma.working = 1.0;
  for (Token t = peek(); t.is("once") || t.is("interpolate") || t.is("map_type") || t.is("repeat") || t.is("offset");
       t = peek()) {
    try_image_item(next(), *image, /*bump=*/true);   // as a bump_map: no value checks
    if (t.is("interpolate") && (image->interpolate < 0 || image->interpolate == 1 || image->interpolate > 4))
      taint(carrier.unsupported, UnsupportedFeature{"material_map interpolate " + std::to_string(image->interpolate) +
                                                        " (POV-Ray's weights are undefined for it)", t.loc});
  }
  carrier.image = std::move(image);
  while (peek().is("texture")) {
    const Token t = next();
    pattern.entries.push_back({static_cast<double>(pattern.entries.size()), parse_texture_block(t)});
  }
  if (pattern.entries.empty()) fail_expected(peek(), "'texture' (a material_map needs at least one texture)");
  expect("}", " closing material_map");
}

bool TextureParser::is_list_pattern_word(const Token& t) const {
  return t.is("checker") || t.is("hexagon") || t.is("brick");
}

// Modifiers and transforms of a patterned texture up to `closer`.
void TextureParser::parse_texture_pattern_modifiers(const Token& first, TexturePattern& pattern,
                                                  std::string_view closer) {
  Pigment& carrier = pattern.pattern;
  for (Token t = next(); !t.is(closer); t = next()) {
    Matrix m;
    if (t.is("texture_map")) {
      const PatternKind k = carrier.pattern;
      if (is_list_pattern(k) || first.is("tiles"))
        fail_at(t, "texture_map cannot be used with this pattern type (as in POV-Ray)");
      pattern.entries = parse_texture_map(t, k == PatternKind::average).texture_entries;
    } else if (try_transform(t, m)) {
      carrier.world_from_pattern = carrier.world_from_pattern * m;
    } else if (t.is("color_map") || t.is("colour_map") || t.is("pigment_map")) {
      fail_at(t, "'" + std::string(t.text) + "' can only be used in a pigment (as in POV-Ray)");
    } else if (try_pattern_modifier(t, carrier)) {
      continue;
    } else if (t.kind == TokenKind::identifier && is_reserved_word(t.text)) {
      taint(carrier.unsupported, skip_unsupported(t, "the texture pattern item '" + std::string(t.text) + "'"));
    } else {
      fail_expected(t, "texture_map, a pattern modifier, a transform or '" + std::string(closer) +
                           "' in the patterned texture");
    }
  }
}

// POV-Ray's Link_Textures: nothing is layered over a patterned texture, and a patterned texture over nothing else.
void TextureParser::refuse_layering(const Token& t, const Texture* existing, bool adding_patterned) const {
  if (existing && existing->patterned()) fail_at(t, "cannot layer over a patterned texture (as in POV-Ray)");
  if (existing && adding_patterned) fail_at(t, "cannot layer a patterned texture over another (as in POV-Ray)");
}

}  // namespace povtrace::sdl
